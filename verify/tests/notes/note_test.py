#!/usr/bin/env python3
"""A note of the corpus, checked from its claims file alone, against its independent derivation.

  note_test.py SIMPSON_VERIFY NOTE_DIR NAME [--without ID,...]

runs NAME.py (sympy: each claim's verdict, the erratum a consequence follows from, and an erratum's
wrong coefficient with the right one, which the harness's correction must name) and
`simpson-verify --paper NAME.tex --claims-file NAME.toml` (validation: the claims file records no
expected verdict), and fails, naming the claim, where the two differ or the note does not read.
--without leaves those claims out of the run (`--claims` the others) and out of the comparison.
"""
import json
import pathlib
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # nothing written into the source tree

from verdicts import compare, report_of

binary, note_dir, name = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
without = set(sys.argv[5].split(",")) if len(sys.argv) > 5 and sys.argv[4] == "--without" else set()
derived = json.loads(subprocess.run([sys.executable, str(note_dir / f"{name}.py")], check=True, capture_output=True, text=True).stdout)
extra = []
if without:
    import tomllib
    ids = [r["id"] for r in tomllib.loads((note_dir / f"{name}.toml").read_text())["claim"]]
    if not without <= set(ids):
        sys.exit(f"FAIL {name}: --without names no claim of the note: {sorted(without - set(ids))}")
    extra = ["--claims", ",".join(i for i in ids if i not in without)]
    derived = {k: v for k, v in derived.items() if k not in without}
report = report_of(binary, name, note_dir / f"{name}.tex", note_dir / f"{name}.toml", extra)


def ginac_text(sympy_text):
    """A coefficient as the harness prints it: GiNaC's canonical text writes 2/3 as (2)/(3)."""
    number = re.fullmatch(r"(-?\d+)/(\d+)", sympy_text)
    return f"({number.group(1)})/({number.group(2)})" if number else sympy_text


def got_of(c):
    got = {"verdict": c["verdict"], **({"follows_from": c["follows_from"]} if "follows_from" in c else {})}
    want = derived.get(c["id"], {}).get("coefficient")
    if want:  # an erratum's wrong coefficient, named with the right one in its correction
        words = f"printed {ginac_text(want['printed'])}, derived {ginac_text(want['derived'])}"
        got["coefficient"] = want if words in c.get("correction", "") else {"correction": c.get("correction", "")}
    return got


sys.exit(1 if compare(name, report, derived, got_of, f"the derivation in {name}.py") else 0)
