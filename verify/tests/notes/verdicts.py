"""What the note corpus's and the shapes' fixtures' tests share: a document run with its claims file,
and its verdicts compared with the ones expected, each difference named."""
import json
import pathlib
import subprocess
import sys
import tempfile


def report_of(binary, name, tex, claims, extra=()):
    """report.json of `simpson-verify --paper TEX --claims-file CLAIMS [EXTRA...]`; exits naming the
    fault when it does not run to verdicts (exit 2: bad input; 3: a harness bug)."""
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([binary, "--paper", str(tex), "--claims-file", str(claims), "--no-certify", "--quiet", "--out", out, *extra],
                             capture_output=True, text=True)
        if run.returncode not in (0, 1):
            sys.exit(f"FAIL {name}: simpson-verify exited {run.returncode}: {run.stderr.strip()}")
        return json.loads((pathlib.Path(out) / "report.json").read_text())


def compare(name, report, expected, got_of, source):
    """Each claim's `got_of(claim)` against `expected[id]` (from `source`, the words a difference names);
    prints every difference and a summary line, and returns how many differ."""
    failures = 0
    seen = set()
    for c in report["claims"]:
        seen.add(c["id"])
        want = expected.get(c["id"])
        if want is None:
            print(f"FAIL {name}: {c['id']}: nothing expected in {source}")
            failures += 1
            continue
        got = got_of(c)
        if got != want:
            print(f"FAIL {name}: {c['id']}: the harness says {got}, {source} {want}\n     note: {c.get('note', '')[:300]}")
            failures += 1
    for claim in sorted(set(expected) - seen):
        print(f"FAIL {name}: {claim}: expected but not in the report")
        failures += 1
    print(f"{name}: {len(seen)} claims, {len(seen) - failures} as expected" if not failures else f"{name}: {failures} difference(s)")
    return failures
