#!/usr/bin/python3
"""report.json against its JSON Schema (verify/app/schema/report.schema.json), for the runs a CI job
makes: a whole scene, claims only, sections only, untimed, the nonlinear section. Altered copies must be rejected, so
that the schema is shown to constrain what it documents. Needs python3-jsonschema (install-deps)."""
import copy
import json
import os
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    sys.exit("FAIL: python3-jsonschema is missing (scripts/install-deps installs it)")

binary, schema_path = sys.argv[1], sys.argv[2]
schema = json.load(open(schema_path))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
failures = 0


def errors(report):
    return sorted(validator.iter_errors(report), key=lambda e: list(e.path))


runs = {
    "quick scene": ["--scene", "quick"],
    "claims only": ["--claims", "phi3-det,gamma-system", "--precisions", "double,rational", "--seed", "7", "--samples", "3"],
    "sections only, untimed": ["--scene", "quick", "--sections", "table1,work_precision", "--no-timing"],
    "timing runs": ["--scene", "quick", "--sections", "work_precision", "--timing-runs", "2", "--precisions", "double,mpfr:30"],
    "sections fpu": ["--scene", "quick", "--sections", "fpu"],
}
with tempfile.TemporaryDirectory() as work:
    # A small nonlinear section (the beyond scene's takes ~30 s): its tables, plots and timing.
    small = {"name": "small-nonlinear", "nonlinear": {"pendulum_N": [10, 20], "energy_steps": 100, "brouwer_steps": 1000,
                                                     "problems": ["pendulum", "kepler"],
                                                     "N": [64, 128], "double_pendulum_N": [10, 20], "max_runs": 1}}
    json.dump(small, open(f"{work}/small-nonlinear.json", "w"))
    runs["nonlinear section"] = ["--scene", f"{work}/small-nonlinear.json"]
    reports, outs = {}, {}
    for name, args in runs.items():
        out = outs[name] = f"{work}/{len(outs)}"
        done = subprocess.run([binary] + os.environ.get("SIMPSON_VERIFY_ARGS", "").split() + ["--quiet", "--out", out] + args, capture_output=True, text=True)
        if done.returncode != 0:
            print(f"FAIL {name}: exit {done.returncode}: {done.stderr.strip()}")
            failures += 1
            continue
        report = json.load(open(f"{out}/report.json"))
        reports[name] = report
        found = errors(report)
        for e in found[:5]:
            print(f"FAIL {name}: {'/'.join(map(str, e.path))}: {e.message[:200]}")
        failures += bool(found)
        if not found:
            print(f"ok   {name}: report.json is valid (schema_version {report['schema_version']})")

    # The same selection into the same directory again: its own report, replaced (exit 0), not "a
    # fuller report" refused. Every section of the registry is a selection's section.
    if "sections fpu" in reports:
        out = outs["sections fpu"]
        again = subprocess.run([binary] + os.environ.get("SIMPSON_VERIFY_ARGS", "").split() + ["--quiet", "--out", out] + runs["sections fpu"],
                               capture_output=True, text=True)
        if again.returncode != 0 or errors(json.load(open(f"{out}/report.json"))):
            print(f"FAIL sections fpu, run again into {out}: exit {again.returncode}: {again.stderr.strip()}")
            failures += 1
        else:
            print("ok   sections fpu, run again into the same directory: exit 0, report.json valid")

    quick = reports.get("quick scene")
    if quick is not None:
        if quick["overrides"] != {} or not quick["timing_files"] or "work_precision" not in quick["experiments"]:
            print("FAIL quick scene: overrides, timing_files or sections not as run")
            failures += 1
        untimed = reports.get("sections only, untimed")
        if untimed is not None and (untimed["timing_files"] or untimed["overrides"].get("timing") is not False):
            print("FAIL untimed: timing files listed or the override not recorded")
            failures += 1

        def altered(change):
            report = copy.deepcopy(quick)
            change(report)
            return report

        alterations = {
            "summary removed": lambda r: r.pop("summary"),
            "an unknown verdict": lambda r: r["claims"][0].update(verdict="maybe"),
            "a newer schema_version": lambda r: r.update(schema_version=4),
            "a run time back in report.json": lambda r: r.update(timing={"total": 1.0}),
            "a short scene digest": lambda r: r["environment"].update(scene_sha256="abc"),
            "a table cell that is an object": lambda r: r["experiments"]["table1"]["entries"][0].update(ours={"x": 1}),
        }
        for name, change in alterations.items():
            if errors(altered(change)):
                print(f"ok   rejected: {name}")
            else:
                print(f"FAIL accepted: {name}")
                failures += 1

sys.exit(1 if failures else 0)
