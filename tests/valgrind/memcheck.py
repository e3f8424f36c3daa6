#!/usr/bin/env python3
"""Runs ctest's tests under valgrind memcheck (tests/valgrind/README.md).

    python3 tests/valgrind/memcheck.py BUILD_DIR [-R REGEX] [-L LABEL] [-E REGEX] [-j N] [--out DIR]

Every test command ctest would run (the same arguments, folder and environment) runs under
memcheck with --leak-check=full; a test fails when it fails on its own, when memcheck reports an
invalid access, an uninitialised value used, a bad free, or a definite or indirect leak
(possibly-lost and still-reachable blocks are not errors). Commands that are cmake -P scripts
are run with --trace-children=yes, so the tools they start are checked too (cmake, sh, gnuplot
and compilers themselves are skipped). The libFuzzer targets (label fuzz, except the replays,
which gcc builds) carry AddressSanitizer and cannot run under valgrind; a sanitizer build
cannot either: use a plain build (e.g. RelWithDebInfo). hwy_timer_shim.c is preloaded (valgrind
3.19 cannot run libhwy's static initializer, which OpenImageIO pulls in). Suppressions: tests/valgrind/mesa.supp,
Mesa/llvmpipe/OSMesa internals only, never a thinlight frame. One log per test in --out
(default BUILD_DIR/memcheck); a summary at the end; the exit status is 1 when any test failed.
"""
import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP_CHILDREN = "*/cmake,*/ctest,*/sh,*/bash,*/dash,*/gnuplot,*/cc,*/gcc,*/g++,*/c++,*/ld,*/collect2,*/cc1,*/as"


def list_tests(build, args):
    cmd = ["ctest", "--test-dir", build, "--show-only=json-v1"]
    for flag in ("R", "L", "E"):
        value = getattr(args, flag)
        if value:
            cmd += ["-" + flag, value]
    data = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    tests = []
    for t in data["tests"]:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        labels = props.get("LABELS", [])
        if "fuzz" in labels and not t["name"].startswith("fuzz_regressions_"):
            continue  # libFuzzer + AddressSanitizer binaries
        if not t.get("command"):
            continue
        tests.append({"name": t["name"], "command": t["command"], "cwd": props.get("WORKING_DIRECTORY", build),
                      "env": props.get("ENVIRONMENT", []), "timeout": float(props.get("TIMEOUT", 1500))})
    return tests


def build_shim(out):
    """hwy_timer_shim.c as a shared library (see the file: valgrind 3.19 and libhwy's RDTSCP)."""
    so = os.path.join(out, "hwy_timer_shim.so")
    subprocess.run(["cc", "-shared", "-fPIC", "-O2", os.path.join(HERE, "hwy_timer_shim.c"), "-o", so], check=True)
    return so


def run_one(test, out, supp, shim):
    log = os.path.join(out, test["name"] + ".log")
    for f in os.listdir(out):  # the logs of an earlier run
        if f == test["name"] + ".log" or f.startswith(test["name"] + ".log."):
            os.remove(os.path.join(out, f))
    scripted = os.path.basename(test["command"][0]) == "cmake"
    vg = ["valgrind", "--tool=memcheck", "--leak-check=full", "--show-leak-kinds=definite,indirect",
          "--errors-for-leak-kinds=definite,indirect", "--error-exitcode=99", "--num-callers=40",
          "--suppressions=" + supp, "--log-file=" + log + (".%p" if scripted else "")]
    if scripted:
        vg += ["--trace-children=yes", "--trace-children-skip=" + SKIP_CHILDREN]
    env = dict(os.environ)
    for kv in test["env"]:
        k, _, v = kv.partition("=")
        env[k] = v
    env["LD_PRELOAD"] = shim
    start = time.time()
    try:
        # valgrind slows programs 20-50 times: the test's own timeout, times 20
        r = subprocess.run(vg + test["command"], cwd=test["cwd"], env=env, capture_output=True, text=True,
                           timeout=max(600.0, test["timeout"] * 20))
        status = r.returncode
        output = r.stdout + r.stderr
    except subprocess.TimeoutExpired:
        status, output = "timeout", ""
    errors, lost = summarize(out, test["name"])
    return test["name"], status, errors, lost, time.time() - start, output


def summarize(out, name):
    """Memcheck's error count and definitely + indirectly lost bytes over the test's logs."""
    errors = lost = 0
    for f in os.listdir(out):
        if f == name + ".log" or f.startswith(name + ".log."):
            text = open(os.path.join(out, f), errors="replace").read()
            if "Memcheck" not in text:
                continue  # a skipped child left an empty log
            for m in re.finditer(r"ERROR SUMMARY: ([0-9,]+) errors", text):
                errors += int(m.group(1).replace(",", ""))
            for m in re.finditer(r"(definitely|indirectly) lost: ([0-9,]+) bytes", text):
                lost += int(m.group(2).replace(",", ""))
    return errors, lost


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("build")
    p.add_argument("-R")
    p.add_argument("-L")
    p.add_argument("-E")
    p.add_argument("-j", type=int, default=1)
    p.add_argument("--out")
    args = p.parse_args()
    build = os.path.abspath(args.build)
    out = os.path.abspath(args.out or os.path.join(build, "memcheck"))
    os.makedirs(out, exist_ok=True)
    supp = os.path.join(HERE, "mesa.supp")
    shim = build_shim(out)
    tests = list_tests(build, args)
    print(f"memcheck: {len(tests)} tests, logs in {out}", flush=True)
    failed = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.j) as pool:
        for name, status, errors, lost, secs, output in pool.map(lambda t: run_one(t, out, supp, shim), tests):
            ok = status == 0 and errors == 0 and lost == 0
            print(f"{'ok  ' if ok else 'FAIL'} {name}: exit {status}, {errors} errors, {lost} bytes lost, {secs:.0f} s",
                  flush=True)
            if not ok:
                failed.append(name)
                if status not in (0, 99):
                    sys.stdout.write(output[-2000:])
    print(f"memcheck: {len(tests) - len(failed)} of {len(tests)} clean" + (": " + " ".join(failed) if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
