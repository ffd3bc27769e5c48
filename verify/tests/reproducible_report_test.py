#!/usr/bin/python3
"""The same scene and seed, run twice from two directories with SOURCE_DATE_EPOCH set, give
byte-identical files, except the files that hold run times (report.json's timing_files). With
--no-timing there are no such files and the whole directories are identical."""
import filecmp
import json
import os
import subprocess
import sys
import tempfile

binary = sys.argv[1]
failures = 0
environment = dict(os.environ, SOURCE_DATE_EPOCH="1693353600")  # 2023-08-30, the first day of GSI 2023


def run(directory, args):
    os.makedirs(directory)
    done = subprocess.run([binary] + os.environ.get("SIMPSON_VERIFY_ARGS", "").split() + ["--quiet", "--scene", "quick", "--out", "out"] + args, cwd=directory, env=environment,
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAIL: exit {done.returncode}: {done.stderr.strip()}")
    return os.path.join(directory, "out")


def listing(directory):
    """The report's files by report-relative path (certificates/<id>.v for a directory's)."""
    return sorted(os.path.relpath(os.path.join(root, name), directory) for root, _, names in os.walk(directory) for name in names)


with tempfile.TemporaryDirectory() as work:
    # The certificates' bytes are compared in the timed pair; the untimed pair skips coqc's run.
    for label, args in (("timed", []), ("untimed", ["--no-timing", "--no-certify"])):
        first, second = run(f"{work}/{label}1", args), run(f"{work}/{label}2", args)
        report = json.load(open(f"{first}/report.json"))
        timing = set(report["timing_files"])
        files = listing(first)
        if files != listing(second):
            print(f"FAIL {label}: the two runs wrote different files")
            failures += 1
        if set(report["files"]) | timing != set(files):
            print(f"FAIL {label}: files and timing_files do not list the directory")
            failures += 1
        compared = [f for f in files if f not in timing]
        _, mismatch, errors = filecmp.cmpfiles(first, second, compared, shallow=False)
        for name in mismatch + errors:
            print(f"FAIL {label}: {name} differs between the two runs")
        failures += len(mismatch) + len(errors)
        if label == "untimed" and timing:
            print(f"FAIL untimed: timing files written: {sorted(timing)}")
            failures += 1
        if label == "timed" and not {"timing.json", "timing.md", "work_precision_time.csv"} <= timing:
            print(f"FAIL timed: the run times are not in their own files: {sorted(timing)}")
            failures += 1
        print(f"ok   {label}: {len(compared) - len(mismatch) - len(errors)} of {len(compared)} files byte-identical"
              f" ({len(timing)} timing files not compared)")
    # The timestamp comes from SOURCE_DATE_EPOCH and says so.
    env = json.load(open(f"{work}/timed1/out/report.json"))["environment"]
    if env["timestamp_utc"] != "2023-08-30T00:00:00Z" or env["timestamp_source"] != "SOURCE_DATE_EPOCH":
        print(f"FAIL timestamp: {env['timestamp_utc']} from {env['timestamp_source']}")
        failures += 1

sys.exit(1 if failures else 0)
