#!/usr/bin/env python3
"""CTest gltf.corpus: writes the corpus of make_corpus.py into WORK_DIR and loads every case with
lidr-load-check, each in its own process under an address-space limit (ulimit -v) and a time limit. A case
passes when the process ends by exit, not by a signal, with the expected exit code (1 for an error, 0 otherwise),
an error message naming the file and containing the case's rule text, or (warning cases) a warning line with it.

    python3 tests/gltf_corpus/run_corpus.py LOAD_CHECK WORK_DIR [--memory-mib 1024] [--jobs 2]
"""
import concurrent.futures
import os
import resource
import signal
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_corpus  # noqa: E402


def run_case(checker, work_dir, case, memory_mib):
    path = os.path.join(work_dir, case["file"])

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (memory_mib << 20, memory_mib << 20))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    try:
        done = subprocess.run([checker, path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, preexec_fn=limit,
                              timeout=60)
    except subprocess.TimeoutExpired:
        return "timed out after 60 s", 0
    out = done.stdout.decode(errors="replace")
    lines = out.splitlines()
    rss = int(lines[-1].split()[1]) if lines and lines[-1].startswith("peak-rss-kib") else 0
    if done.returncode < 0:
        return "killed by signal %s\n%s" % (signal.Signals(-done.returncode).name, out[-2000:]), rss
    expect, message = case["expect"], case["message"]
    if expect == "error":
        if done.returncode != 1:
            return "expected exit 1 (error), got %d\n%s" % (done.returncode, out[-2000:]), rss
        error = next((l for l in lines if l.startswith("error ")), "")
        name = os.path.basename(case["file"])
        if name not in error or message not in error:
            return "expected an error naming %s with '%s', got:\n%s" % (name, message, out[-2000:]), rss
    else:
        if done.returncode != 0:
            return "expected exit 0, got %d\n%s" % (done.returncode, out[-2000:]), rss
        warnings = [l for l in lines if l.startswith("warning ")]
        if expect == "warning" and not any(message in w for w in warnings):
            return "expected a warning with '%s', got:\n%s" % (message, out[-2000:]), rss
    return None, rss


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    checker, work_dir = argv[1], argv[2]
    memory_mib = int(argv[argv.index("--memory-mib") + 1]) if "--memory-mib" in argv else 1024
    jobs = int(argv[argv.index("--jobs") + 1]) if "--jobs" in argv else 2
    start = time.time()
    cases = make_corpus.write(make_corpus.build(), work_dir)
    failures, peak = [], (0, "")
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        results = pool.map(lambda case: (case, run_case(checker, work_dir, case, memory_mib)), cases)
        for case, (problem, rss) in results:
            if rss > peak[0]:
                peak = (rss, case["name"])
            if problem:
                failures.append(case["name"])
                print("FAIL %s (%s): %s" % (case["name"], case["file"], problem))
    counts = {kind: sum(1 for c in cases if c["expect"] == kind) for kind in ("error", "ok", "warning")}
    print("%d cases (%d errors, %d ok, %d warnings), %d failed, in %.1f s; address space limited to %d MiB; "
          "highest peak RSS %.1f MiB (%s)" % (len(cases), counts["error"], counts["ok"], counts["warning"],
                                              len(failures), time.time() - start, memory_mib, peak[0] / 1024.0, peak[1]))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
