#!/usr/bin/python3
"""Why each failed ctest test failed, in a few lines, printed after the run.

  failed_test_summary.py BUILD_DIR [--lines N]

A failing integration test prints its checks' FAIL lines in the middle of a long output; a CI log
that is shown cut (its head and its tail) then says which tests failed but not why. This reads
ctest's own record of the last run (Testing/Temporary/LastTestsFailed.log and LastTest.log) and
prints, per failed test, the lines that say FAIL (or ERROR, Assertion, AddressSanitizer,
runtime error) and the output's last lines. Exit 0 also when nothing failed or ctest left no
record (it only reports); 64 on a usage error.
"""
import argparse
import os
import re
import sys

SAYS_WHY = re.compile(r"FAIL|ERROR|Assertion|AddressSanitizer|LeakSanitizer|runtime error|Timeout|Failure")


def test_outputs(last_test_log):
    """{test name: (output lines, verdict line)} from ctest's LastTest.log."""
    outputs = {}
    name, lines, in_output = None, [], False
    with open(last_test_log, errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            m = re.match(r"^\d+/\d+ Test: (.+)$", line)
            if m:
                name, lines, in_output = m.group(1), [], False
                continue
            if name is None:
                continue
            if line == "Output:":
                in_output = True
                continue
            if in_output and line.startswith("<end of output>"):
                in_output = False
                continue
            if in_output:
                if not line.startswith("----------"):
                    lines.append(line)
                continue
            if line.startswith("Test ") and (line.endswith("Failed.") or line.endswith("Passed.")
                                             or "Timeout" in line or "Exception" in line):
                outputs[name] = (lines, line)
    return outputs


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("build_dir")
    parser.add_argument("--lines", type=int, default=25, help="at most this many lines per test")
    args = parser.parse_args()
    if args.lines < 1:
        parser.error("--lines wants at least 1")
    temporary = os.path.join(args.build_dir, "Testing", "Temporary")
    failed_log = os.path.join(temporary, "LastTestsFailed.log")
    if not os.path.exists(failed_log):
        print(f"failed_test_summary: no {failed_log}: nothing recorded as failed")
        return 0
    with open(failed_log) as f:
        failed = [line.strip().split(":", 1)[-1] for line in f if line.strip()]
    last_test_log = os.path.join(temporary, "LastTest.log")
    outputs = test_outputs(last_test_log) if os.path.exists(last_test_log) else {}
    print(f"== why {len(failed)} test(s) failed (from {last_test_log})")
    for name in failed:
        lines, verdict = outputs.get(name, ([], "no output recorded"))
        why = [line for line in lines if SAYS_WHY.search(line)]
        tail = [line for line in lines[-5:] if line not in why]
        shown = (why[: args.lines - len(tail)] if len(why) + len(tail) > args.lines else why) + tail
        print(f"-- {name}: {verdict}")
        for line in shown:
            print(f"   {line[:300]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
