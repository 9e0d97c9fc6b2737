#!/usr/bin/python3
"""Decides whether a failed sanitizer suite may be retried (scripts/sanitize.sh).

LeakSanitizer's stop-the-world tracer can crash at exit ("Tracer caught signal 11") after the
test body has passed, a fault of the sanitizer runtime, not of the test (the cause seen so far,
its __tls_get_addr interceptor, is turned off in environment.sh; this guards against others). Reads ctest's JUnit report and
exits 0 only when every failed test's output shows that crash and nothing else wrong, so that
only those are run again; any other failure (a leak, an ASan or UBSan finding, a failed
assertion) exits 1 and fails the suite as it is. Debian's /usr/bin/python3, standard library only.
"""
import sys
import xml.etree.ElementTree as ElementTree

TRACER_CRASH = "Tracer caught signal"
LSAN_FATAL = "LeakSanitizer has encountered a fatal error"
# What a real failure prints: GoogleTest's verdict, ASan's and UBSan's reports, a found leak.
OTHER_FAULTS = ("[  FAILED  ]", "ERROR: AddressSanitizer", "runtime error:",
                "detected memory leaks")


def failed_cases(report_path):
    for case in ElementTree.parse(report_path).getroot().iter("testcase"):
        if case.get("status") == "run":
            continue
        output = "".join(node.text or "" for node in case.iter("system-out"))
        yield case.get("name"), output


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: rerun_tracer_crashes.py JUNIT_REPORT")
    failures = list(failed_cases(sys.argv[1]))
    if not failures:
        sys.exit("sanitize: ctest failed but its report names no failed test")
    retry = True
    for name, output in failures:
        crash_only = (TRACER_CRASH in output and LSAN_FATAL in output
                      and not any(fault in output for fault in OTHER_FAULTS))
        verdict = "LeakSanitizer's tracer crashed after the test passed" if crash_only else "failed"
        print(f"sanitize: {name}: {verdict}")
        retry = retry and crash_only
    sys.exit(0 if retry else 1)


if __name__ == "__main__":
    main()
