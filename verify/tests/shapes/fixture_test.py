#!/usr/bin/env python3
"""A proof shape's fixture folder, run as a user runs a note: note.tex with its claims.toml.

  fixture_test.py SIMPSON_VERIFY FIXTURE_DIR

Each folder under verify/tests/shapes/ holds note.tex, a short document, and claims.toml, whose
every record states its `expected` verdict with its derivation by hand in a comment beside it. The
folder passes when `simpson-verify --paper note.tex --claims-file claims.toml` gives every record its
expected verdict, and every record expecting a remark (`expected = "holds"` with its class in
`finding`) that remark's class, and no other record a remark. A folder must hold a statement the
shape refuses (a verdict other than holds) or one it holds with a remark, so that a shape that stopped
telling right from wrong fails it. A record's `follows_from` names the claim it is a consequence of:
the report must trace it to that cause, and a record without one to none.
"""
import pathlib
import sys

sys.dont_write_bytecode = True  # nothing written into the source tree
import tomllib

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "notes"))
from verdicts import compare, report_of  # noqa: E402

binary, folder = sys.argv[1], pathlib.Path(sys.argv[2])
name = folder.name
records = tomllib.loads((folder / "claims.toml").read_text())["claim"]
expected = {}
for r in records:
    if "expected" not in r:
        sys.exit(f"FAIL {name}: record '{r['id']}' states no expected verdict")
    remark = r.get("finding") if r["expected"] == "holds" else None
    expected[r["id"]] = r["expected"] + (f", with a remark ({remark})" if remark else "")
if all(v == "holds" for v in expected.values()):
    sys.exit(f"FAIL {name}: every record holds without a remark; a fixture needs a statement its shape refuses or remarks")
report = report_of(binary, name, folder / "note.tex", folder / "claims.toml")
follows = {r["id"]: r.get("follows_from") for r in records}
for r in records:
    if follows[r["id"]]:
        expected[r["id"]] += f", following from {follows[r['id']]}"
got = lambda c: (c["verdict"] + (f", with a remark ({c['remark']['class']})" if "remark" in c else "") +
                 (f", following from {c['follows_from']}" if c.get("follows_from") else ""))
sys.exit(1 if compare(name, report, expected, got, "claims.toml's expected") else 0)
