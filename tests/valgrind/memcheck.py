#!/usr/bin/env python3
"""Runs ctest's tests under valgrind memcheck, resumably (tests/valgrind/README.md).

    python3 tests/valgrind/memcheck.py BUILD_DIR [-R REGEX] [-L LABEL] [-E REGEX] [-j N] [--out DIR]
                                      [--order ctest|cost|name] [--cost-data FILE] [--force] [--list [-v]]

Every test command ctest would run (the same arguments, folder and environment) runs under
memcheck with --leak-check=full; a test fails when it fails on its own, when memcheck reports an
invalid access, an uninitialised value used, a bad free, or a definite or indirect leak
(possibly-lost and still-reachable blocks are not errors). Every test runs with
--trace-children=yes, so the project's programs it starts (a cmake -P check's tools, the viewer
started through system()) are checked too; programs in system folders (cmake, compilers, nm,
gnuplot, python, xvfb-run) are not traced, except /bin/sh, and their logs do not count. With
DISPLAY unset an Xvfb is started for the run, so the viewer tests start the viewer through the
traced /bin/sh instead of the untraced xvfb-run. The libFuzzer targets (label fuzz, except the replays,
which gcc builds) carry AddressSanitizer and cannot run under valgrind; a sanitizer build
cannot either: use a plain build (e.g. RelWithDebInfo). hwy_timer_shim.c is preloaded (valgrind
3.19 cannot run libhwy's static initializer, which OpenImageIO pulls in). Suppressions:
tests/valgrind/mesa.supp, Mesa/llvmpipe/OSMesa internals and one false report of glibc's ld.so,
never a thinlight frame. One log per process in --out (default BUILD_DIR/memcheck).

Resuming: --out holds results.json (runs sharing it merge their records), one record per test (its
fingerprint, status, wall and CPU seconds, memcheck's error count, lost bytes and first reports),
rewritten atomically after every test. A test already clean for the same fingerprint is skipped
unless --force. The fingerprint is the sha256 of the command line, environment and folder, of every
file the command names (the test executable, a cmake -P script and the tool it is given), of the
build tree's shared libraries those executables load (ldd); not of the suppressions (adding an entry
cannot make a clean test dirty; after removing or narrowing one, run with --force). Killing the
script at any time (SIGINT, SIGTERM, even SIGKILL: the running valgrind gets SIGKILL when its parent
dies) loses only the test being run, which stays pending. --list prints the clean / failed / pending
counts and starts nothing. Every result also goes to the ledger (--ledger, default
tests/valgrind/ledger.json, committed), keyed by the sources tracked at HEAD, the build type, the
toolchain's package versions and the test's command: a test clean there for its key now is
skipped too, so a run resumes on a fresh checkout with a new build folder. --order cost runs the
cheapest tests first, by ctest's cost data (BUILD_DIR/Testing/Temporary/CTestCostData.txt, or
--cost-data FILE; tests without data last), so most tests are covered early. The exit status is 1
when a test run now, or an earlier failure not rerun, failed.
"""
import argparse
import datetime
import fcntl
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
# Programs outside the project (cmake, shells, compilers, nm, gnuplot, python, ...): the children
# of a test that are not traced, and the logs that do not count (a cmake -P check's cmake)
SYSTEM_DIRS = ("/usr/", "/bin/", "/sbin/", "/lib/", "/lib64/", "/opt/", "/snap/", sys.base_prefix.rstrip("/") + "/")
# not traced: every program there but /bin/sh (valgrind's patterns have only * and ?: two-letter
# names in /bin are traced too, and cost a second each), through which system() and popen() start
# the project's programs (the viewer tests, the kill-mid-write test)
SKIP_CHILDREN = ",".join([d + "*" for d in SYSTEM_DIRS if d != "/bin/"] + ["/bin/?", "/bin/???*"])
RESULTS = "results.json"
# memcheck's report headlines, kept (deduplicated, at most MAX_REPORTS) as the error summary
REPORT = re.compile(r"==\d+== ((?:Invalid (?:read|write|free)|Conditional jump|Use of uninitialised|Syscall param|"
                    r"Mismatched free|Source and destination overlap|Argument '.*' of function|"
                    r"\S+ bytes in \S+ blocks are (?:definitely|indirectly) lost).*)")
FRAME = re.compile(r"==\d+==    (?:at|by) 0x[0-9A-F]+: (.*)")
MAX_REPORTS = 5


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
                      "env": props.get("ENVIRONMENT", []), "timeout": float(props.get("TIMEOUT", 1500)),
                      "setup": props.get("FIXTURES_SETUP", []), "required": props.get("FIXTURES_REQUIRED", []),
                      "cleanup": props.get("FIXTURES_CLEANUP", []), "depends": props.get("DEPENDS", [])})
    return tests


def with_prerequisites(todo, tests):
    """todo with, before each test, the tests it needs (ctest's DEPENDS and the FIXTURES_SETUP tests
    of its FIXTURES_REQUIRED, run again even when already clean: what they make may be gone), and
    fixture cleanup tests last. Returns (tests in order, {name: names it waits for})."""
    by_name = {t["name"]: t for t in tests}
    setups = {}
    for t in tests:
        for f in t["setup"]:
            setups.setdefault(f, []).append(t["name"])

    def needs(t):
        return [n for n in t["depends"] + [s for f in t["required"] for s in setups.get(f, [])] if n in by_name]

    out, placed, waits = [], set(), {}

    def place(t):
        if t["name"] in placed:
            return
        placed.add(t["name"])
        for n in needs(t):
            place(by_name[n])
        waits[t["name"]] = needs(t)
        out.append(t)

    for t in todo:
        if not t["cleanup"]:
            place(t)
    for t in todo:
        if t["cleanup"]:
            place(t)
    return out, waits


# ---- fingerprints -------------------------------------------------------------------------------

class Fingerprints:
    """sha256 of what a test runs; file hashes and ldd answers cached for the run."""

    def __init__(self, build, supp):
        self.build = os.path.realpath(build)
        self.supp = supp
        self.hashes = {}
        self.libs = {}
        self.lock = threading.Lock()

    def file_hash(self, path):
        st = os.stat(path)
        key = (path, st.st_mtime_ns, st.st_size)
        with self.lock:
            if key in self.hashes:
                return self.hashes[key]
        h = hashlib.sha256()
        with open(path, "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
        with self.lock:
            self.hashes[key] = h.hexdigest()
        return self.hashes[key]

    def build_libs(self, exe):
        """The shared libraries of the build tree that exe loads (libthinlight.so, ...)."""
        with self.lock:
            if exe in self.libs:
                return self.libs[exe]
        found = []
        r = subprocess.run(["ldd", exe], capture_output=True, text=True)
        for m in re.finditer(r"=> (/\S+)", r.stdout if r.returncode == 0 else ""):
            lib = os.path.realpath(m.group(1))
            if lib.startswith(self.build + os.sep):
                found.append(lib)
        with self.lock:
            self.libs[exe] = sorted(set(found))
        return self.libs[exe]

    def of(self, test):
        """(fingerprint, {file: sha256}) of a test, or (None, {}) when a file it names is missing."""
        files = {}
        for arg in test["command"]:
            path = arg.split("=", 1)[1] if arg.startswith("-D") and "=" in arg else arg
            if os.path.isabs(path) and os.path.isfile(path):
                files[path] = None
                if os.access(path, os.X_OK):
                    for lib in self.build_libs(path):
                        files[lib] = None
        if not os.path.isfile(test["command"][0]):
            return None, {}  # not built (EXE_NOT_BUILT)
        try:
            files = {f: self.file_hash(f) for f in sorted(files)}
        except OSError:
            return None, {}
        h = hashlib.sha256(json.dumps([test["command"], test["env"], test["cwd"], files]).encode())
        return h.hexdigest(), files


# ---- the results file ---------------------------------------------------------------------------

def write_json(path, data):
    """data as JSON at path, written to a temporary name and renamed: a kill leaves the old file."""
    tmp = f"{path}.{os.getpid()}.tmp"
    with open(tmp, "w") as f:
        json.dump(data, f, indent=1, sort_keys=True)
        f.write("\n")
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


class Results:
    """results.json in --out: {test name: record}, rewritten to a temporary name and renamed."""

    def __init__(self, out):
        self.path = os.path.join(out, RESULTS)
        self.lock = threading.Lock()
        try:
            with open(self.path) as f:
                self.records = json.load(f)
        except FileNotFoundError:
            self.records = {}
        except (OSError, ValueError) as e:
            sys.exit(f"memcheck: cannot read {self.path}: {e}")

    def clean(self, name, fingerprint):
        r = self.records.get(name)
        return r is not None and fingerprint is not None and r["fingerprint"] == fingerprint and r["status"] == "clean"

    def state(self, name, fingerprint):
        r = self.records.get(name)
        if r is None or fingerprint is None or r["fingerprint"] != fingerprint:
            return "pending"
        return "clean" if r["status"] == "clean" else "failed"

    def put(self, name, record):
        """Adds one record, merged into the file as it is now (another run may share --out)."""
        with self.lock, open(self.path + ".lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            try:
                with open(self.path) as f:
                    self.records.update(json.load(f))
            except (OSError, ValueError):
                pass
            self.records[name] = record
            write_json(self.path, self.records)


# ---- the ledger: results that outlive the build folder ------------------------------------------

# what a test's key leaves out: prose, CI scripts and this folder (the script, its suppressions and
# the ledger itself); everything else tracked (sources, shaders, tests, examples, data, the code
# in docs/) is in it
LEDGER_SKIP = re.compile(r"(\.md$|^LICENSE$|^\.gitignore$|^\.ci/|^tests/valgrind/)")
# the toolchain and libraries a result depends on beyond the sources
LEDGER_PACKAGES = ("gcc-12", "g++-12", "libc6", "valgrind", "libosmesa6", "libgl1-mesa-dri", "libegl-mesa0",
                   "libglfw3", "libopenimageio2.4", "libtinygltf-dev", "nlohmann-json3-dev", "libllvm15")


class Ledger:
    """tests/valgrind/ledger.json, kept in the repository: per test the key of the sources and
    toolchain it ran at (not of the binaries, which every session builds anew), its status and
    figures. A test clean in the ledger for the key it has now is skipped, so a run spread over
    sessions on fresh checkouts resumes where the last commit of the ledger left it. Disabled,
    with a line saying why, when the work tree differs from HEAD in a file the key covers."""

    def __init__(self, path, build):
        self.path = path
        self.build = os.path.realpath(build)
        self.root = os.path.realpath(os.path.join(HERE, "..", ".."))
        self.lock = threading.Lock()
        self.base, self.why = self._base()
        try:
            with open(path) as f:
                self.data = json.load(f)
        except FileNotFoundError:
            self.data = {}
        except (OSError, ValueError) as e:
            sys.exit(f"memcheck: cannot read {path}: {e}")
        self.data.setdefault("tests", {})

    def _git(self, *args):
        return subprocess.run(["git", "-C", self.root] + list(args), capture_output=True, text=True)

    def _base(self):
        """(sha256 of the tracked files the key covers and the toolchain, None) or (None, why not)."""
        head = self._git("rev-parse", "HEAD")
        if head.returncode != 0:
            return None, "not a git checkout"
        dirty = [line[3:] for line in self._git("status", "--porcelain").stdout.splitlines()
                 if not LEDGER_SKIP.search(line[3:].split(" -> ")[-1])]
        if dirty:
            return None, f"the work tree differs from HEAD ({dirty[0]}{' ...' if len(dirty) > 1 else ''})"
        files = [line for line in self._git("ls-tree", "-r", "HEAD").stdout.splitlines()
                 if not LEDGER_SKIP.search(line.split("\t", 1)[1])]
        cache = {}
        try:
            with open(os.path.join(self.build, "CMakeCache.txt")) as f:
                for line in f:
                    m = re.match(r"(CMAKE_BUILD_TYPE|CMAKE_C_COMPILER|CMAKE_CXX_COMPILER|THINLIGHT_\w+):\w+=(.*)", line)
                    if m:
                        cache[m.group(1)] = m.group(2).strip()
        except OSError:
            return None, "no CMakeCache.txt in the build folder"
        q = subprocess.run(["dpkg-query", "-W", "-f", "${Package}=${Version}\n"] + list(LEDGER_PACKAGES),
                           capture_output=True, text=True)
        packages = sorted(q.stdout.split())
        self.commit = head.stdout.strip()
        h = hashlib.sha256(json.dumps([files, cache, packages]).encode())
        return h.hexdigest(), None

    def key(self, test):
        """The test's key: the base and its command, environment and folder with the build and
        source folders' paths replaced (they may lie elsewhere in another session)."""
        if self.base is None:
            return None

        def norm(s):
            return s.replace(self.build, "<build>").replace(self.root, "<source>")
        what = [[norm(a) for a in test["command"]], [norm(e) for e in test["env"]], norm(test["cwd"])]
        return hashlib.sha256(json.dumps([self.base, what]).encode()).hexdigest()

    def clean(self, name, key):
        r = self.data["tests"].get(name)
        return key is not None and r is not None and r["key"] == key and r["status"] == "clean"

    def put(self, name, key, record):
        if key is None:
            return
        if self._base()[0] != self.base:  # a commit or an edit since the start: the build may not be HEAD's
            print(f"memcheck: {name} not put in the ledger: the sources changed during the run", flush=True)
            return
        keep = ("status", "exit", "errors", "lost_bytes", "reports", "wall_s", "cpu_s", "when")
        # another run may write the ledger too: lock its folder (no lock file left in the tree)
        folder = os.open(os.path.dirname(os.path.abspath(self.path)), os.O_RDONLY)
        try:
            with self.lock:
                fcntl.flock(folder, fcntl.LOCK_EX)
                try:
                    with open(self.path) as f:
                        self.data["tests"].update(json.load(f).get("tests", {}))
                except (OSError, ValueError):
                    pass
                self.data["tests"][name] = dict({"key": key, "commit": self.commit[:12]},
                                                **{k: record[k] for k in keep})
                write_json(self.path, self.data)
        finally:
            os.close(folder)  # releases the lock


# ---- running one test ---------------------------------------------------------------------------

LIVE = set()  # the valgrind processes running now, killed with the script
LIVE_LOCK = threading.Lock()
# a killed script leaves no valgrind behind: PR_SET_PDEATHSIG, through util-linux's setpriv
DIE_WITH_PARENT = ["setpriv", "--pdeathsig", "KILL"]


def build_shim(out):
    """hwy_timer_shim.c as a shared library (see the file: valgrind 3.19 and libhwy's RDTSCP)."""
    so = os.path.join(out, "hwy_timer_shim.so")
    subprocess.run(["cc", "-shared", "-fPIC", "-O2", os.path.join(HERE, "hwy_timer_shim.c"), "-o", so], check=True)
    return so


def logs_of(out, name):
    return [os.path.join(out, f) for f in os.listdir(out) if f == name + ".log" or f.startswith(name + ".log.")]


def run_one(test, out, supp, shim):
    """Runs test under memcheck: (exit status or 'timeout', wall s, cpu s, the program's output)."""
    for f in logs_of(out, test["name"]):  # the logs of an earlier run
        os.remove(f)
    log = os.path.join(out, test["name"] + ".log")
    # every process the test starts outside system folders is traced, one log each; the test's
    # own verdict stands and memcheck's reports are counted from the logs (summarize)
    # --keep-debuginfo: a library unloaded before the leak check (the viewer's DRI driver) still
    # names its frames, so that mesa.supp can match them
    vg = ["valgrind", "--tool=memcheck", "--leak-check=full", "--show-leak-kinds=definite,indirect",
          "--errors-for-leak-kinds=definite,indirect", "--num-callers=40", "--keep-debuginfo=yes",
          "--suppressions=" + supp, "--log-file=" + log + ".%p", "--trace-children=yes",
          "--trace-children-skip=" + SKIP_CHILDREN]
    env = dict(os.environ)
    for kv in test["env"]:
        k, _, v = kv.partition("=")
        env[k] = v
    env["LD_PRELOAD"] = shim
    # Mesa's disk-cache writer thread loses the blob of a job still in flight at exit (3.5-4 KB
    # "definitely lost" under glLinkProgram, now and then): no cache, no race (README.md)
    env.setdefault("MESA_SHADER_CACHE_DISABLE", "true")
    # valgrind runs one thread at a time anyway; llvmpipe rasterizing in the calling thread
    # instead of handing tiles to its own threads saves a fifth of the CPU time (README.md)
    env.setdefault("LP_NUM_THREADS", "0")
    # and with 128-bit vectors (SSE) in its generated code instead of AVX's 256: 8-9 % less CPU
    # time under memcheck, the same result (README.md)
    env.setdefault("LP_NATIVE_VECTOR_WIDTH", "128")
    output_path = os.path.join(out, test["name"] + ".out")
    # valgrind slows programs 20-50 times: the test's own timeout, times 20
    limit = max(600.0, test["timeout"] * 20)
    start = time.time()
    with open(output_path, "w") as output:
        p = subprocess.Popen(DIE_WITH_PARENT + vg + test["command"], cwd=test["cwd"], env=env, stdout=output,
                             stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)
        with LIVE_LOCK:
            LIVE.add(p)
        timed_out = []
        timer = threading.Timer(limit, lambda: (timed_out.append(True), _kill(p)))
        timer.start()
        try:
            _, status, usage = os.wait4(p.pid, 0)
        finally:
            timer.cancel()
            with LIVE_LOCK:
                LIVE.discard(p)
    p.returncode = os.waitstatus_to_exitcode(status)
    wall = time.time() - start
    code = "timeout" if timed_out else p.returncode
    with open(output_path, errors="replace") as f:
        text = f.read()
    return code, wall, usage.ru_utime + usage.ru_stime, text


def _kill(p):
    try:
        os.killpg(p.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def summarize(out, name):
    """Memcheck's error count, definitely + indirectly lost bytes and first reports over the test's logs."""
    errors = lost = 0
    reports = []
    for path in logs_of(out, name):
        text = open(path, errors="replace").read()
        if "Memcheck" not in text:
            continue  # a skipped child left an empty log
        command = re.search(r"==\d+== Command: (\S+)", text)
        if command and command.group(1).startswith(SYSTEM_DIRS):
            continue  # a cmake -P check's cmake: not the project's code
        for m in re.finditer(r"ERROR SUMMARY: ([0-9,]+) errors", text):
            errors += int(m.group(1).replace(",", ""))
        for m in re.finditer(r"(definitely|indirectly) lost: ([0-9,]+) bytes", text):
            lost += int(m.group(2).replace(",", ""))
        lines = text.splitlines()
        for i, line in enumerate(lines):
            m = REPORT.match(line)
            if not m or len(reports) >= 4 * MAX_REPORTS:
                continue
            frames = [FRAME.match(x).group(1) for x in lines[i + 1:i + 12] if FRAME.match(x)]
            ours = [f for f in frames if re.search(r"\btl_|tl_gltf::|tl_io::|thinlight", f)]
            report = m.group(1) + " at " + ((ours or frames or ["?"])[0])
            if report not in reports:
                reports.append(report)
    # accesses and uninitialised values first, then definite leaks, then indirect ones
    reports.sort(key=lambda x: 2 if "indirectly lost" in x else 1 if "definitely lost" in x else 0)
    return errors, lost, reports[:MAX_REPORTS]


def record_of(test, fingerprint, files, code, wall, cpu, out):
    errors, lost, reports = summarize(out, test["name"])
    if code == "timeout":
        status = "timeout"
    elif code == 0 and errors == 0 and lost == 0:
        status = "clean"
    elif code == 0:
        status = "memcheck"
    else:
        status = f"exit {code}"
    return {"fingerprint": fingerprint, "files": files, "status": status, "exit": code, "errors": errors,
            "lost_bytes": lost, "reports": reports, "wall_s": round(wall, 1), "cpu_s": round(cpu, 1),
            "when": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")}


# ---- ordering, listing, the run -----------------------------------------------------------------

def read_costs(path):
    """ctest's cost data: 'name runs cost' lines up to '---'."""
    costs = {}
    try:
        with open(path) as f:
            for line in f:
                if line.startswith("---"):
                    break
                parts = line.split()
                if len(parts) == 3:
                    costs[parts[0]] = float(parts[2])
    except OSError:
        pass
    return costs


def ordered(tests, order, cost_path):
    if order == "name":
        return sorted(tests, key=lambda t: t["name"])
    if order == "cost":
        costs = read_costs(cost_path)
        if not costs:
            print(f"memcheck: no cost data in {cost_path}; ctest's order", flush=True)
        return sorted(tests, key=lambda t: (t["name"] not in costs, costs.get(t["name"], 0.0)))
    return tests


def print_list(tests, prints, results, ledger, verbose):
    counts = {"clean": 0, "failed": 0, "pending": 0}
    for t in tests:
        state = results.state(t["name"], prints[t["name"]])
        r = results.records.get(t["name"])
        if state == "pending" and ledger.clean(t["name"], ledger.key(t)):
            state, r = "clean", ledger.data["tests"][t["name"]]
        counts[state] += 1
        if verbose or state == "failed":
            extra = f" ({r['status']}, {r['wall_s']} s, {r['errors']} errors, {r['lost_bytes']} bytes lost)" \
                if r and state != "pending" else ""
            print(f"{state:8} {t['name']}{extra}")
            if state == "failed":
                for rep in r["reports"]:
                    print("         " + rep)
    done = counts["clean"] + counts["failed"]
    print(f"memcheck: {done} of {len(tests)} done ({counts['clean']} clean, {counts['failed']} failed), "
          f"{counts['pending']} pending")
    return 1 if counts["failed"] else 0


def run_all(todo, waits, fp, results, ledger, out, supp, shim, jobs, force):
    """Runs the tests of todo on jobs threads, each after the tests it waits for; returns the names
    of those that failed."""
    failed = []
    queue = list(todo)
    qlock = threading.Condition()
    finished = set()
    prerequisites = {n for names in waits.values() for n in names}

    def worker():
        while True:
            with qlock:
                if not queue:
                    return
                t = queue.pop(0)
                qlock.wait_for(lambda: all(n in finished for n in waits.get(t["name"], [])))
            try:
                run_test(t)
            finally:
                with qlock:
                    finished.add(t["name"])
                    qlock.notify_all()

    def run_test(t):
        if t["name"] not in prerequisites and not force and (results.clean(t["name"], fp.of(t)[0]) or
                                                             ledger.clean(t["name"], ledger.key(t))):
            return
        before, files_before = fp.of(t)  # what runs now (the build may have changed since the start)
        code, wall, cpu, output = run_one(t, out, supp, shim)
        after, _ = fp.of(t)
        rec = record_of(t, before, files_before, code, wall, cpu, out)
        if after != before:  # rebuilt while it ran: no result for either build
            rec["status"], rec["fingerprint"] = "rebuilt while running", None
        results.put(t["name"], rec)
        if rec["fingerprint"] is not None:
            ledger.put(t["name"], ledger.key(t), rec)
        ok = rec["status"] == "clean"
        with qlock:
            print(f"{'ok  ' if ok else 'FAIL'} {t['name']}: {rec['status']}, exit {code}, {rec['errors']} errors, "
                  f"{rec['lost_bytes']} bytes lost, {wall:.0f} s wall, {cpu:.0f} s cpu", flush=True)
            if not ok:
                failed.append(t["name"])
                for rep in rec["reports"]:
                    print("     " + rep, flush=True)
                if rec["status"] not in ("memcheck",):
                    sys.stdout.write(output[-2000:])

    threads = [threading.Thread(target=worker, daemon=True) for _ in range(max(1, jobs))]
    for th in threads:
        th.start()
    for th in threads:
        while th.is_alive():
            th.join(0.5)  # wakes for signals
    return failed


def start_display():
    """An Xvfb server for the run when DISPLAY is unset (the viewer tests need one): with DISPLAY
    set they start the viewer through /bin/sh, which is traced, instead of through xvfb-run, which
    is a system program and would hide the viewer from memcheck. None when not started."""
    if os.environ.get("DISPLAY") or not shutil.which("Xvfb"):
        return None
    r, w = os.pipe()
    xvfb = ["Xvfb", "-displayfd", str(w), "-screen", "0", "1280x1024x24", "-nolisten", "tcp"]
    server = subprocess.Popen(DIE_WITH_PARENT + xvfb, pass_fds=(w,), stdin=subprocess.DEVNULL,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    os.close(w)
    with os.fdopen(r) as f:
        number = f.readline().strip()  # written once the server accepts clients; empty if it died
    if not number.isdigit():
        server.kill()
        print("memcheck: Xvfb did not start; the viewer tests run the viewer untraced, under xvfb-run", flush=True)
        return None
    os.environ["DISPLAY"] = ":" + number  # the server dies with the script (DIE_WITH_PARENT)
    return server


def stop(signum, frame):
    with LIVE_LOCK:
        for p in list(LIVE):
            _kill(p)
    print(f"memcheck: stopped by signal {signum}; the tests being run stay pending", flush=True)
    os._exit(128 + signum)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("build")
    p.add_argument("-R")
    p.add_argument("-L")
    p.add_argument("-E")
    p.add_argument("-j", type=int, default=1)
    p.add_argument("--out")
    p.add_argument("--order", choices=("ctest", "cost", "name"), default="ctest")
    p.add_argument("--cost-data", help="ctest's CTestCostData.txt (default: the build's)")
    p.add_argument("--force", action="store_true", help="rerun tests already clean for the same fingerprint")
    p.add_argument("--list", action="store_true", help="print clean / failed / pending counts, run nothing")
    p.add_argument("-v", "--verbose", action="store_true", help="with --list: one line per test")
    p.add_argument("--ledger", default=os.path.join(HERE, "ledger.json"),
                   help="the results kept in the repository (default: tests/valgrind/ledger.json)")
    args = p.parse_args()
    build = os.path.abspath(args.build)
    out = os.path.abspath(args.out or os.path.join(build, "memcheck"))
    os.makedirs(out, exist_ok=True)
    supp = os.path.join(HERE, "mesa.supp")
    tests = list_tests(build, args)
    fp = Fingerprints(build, supp)
    prints, files = {}, {}
    for t in tests:
        prints[t["name"]], files[t["name"]] = fp.of(t)
    results = Results(out)
    ledger = Ledger(os.path.abspath(args.ledger), build)
    if ledger.why:
        print(f"memcheck: the ledger is not read or written: {ledger.why}", flush=True)
    elif not args.list:
        # what runs must be what the key names: HEAD's sources, built (seconds when up to date)
        if subprocess.run(["cmake", "--build", build, "-j2"], stdout=subprocess.DEVNULL).returncode != 0:
            sys.exit("memcheck: the build folder does not build")
        for t in tests:
            prints[t["name"]], files[t["name"]] = fp.of(t)
    if args.list:
        return print_list(tests, prints, results, ledger, args.verbose)
    cost_path = args.cost_data or os.path.join(build, "Testing", "Temporary", "CTestCostData.txt")
    tests = ordered(tests, args.order, cost_path)
    todo = [t for t in tests if args.force or not (results.clean(t["name"], prints[t["name"]]) or
                                                   ledger.clean(t["name"], ledger.key(t)))]
    todo, waits = with_prerequisites(todo, tests)
    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    shim = build_shim(out)
    start_display()
    print(f"memcheck: {len(tests)} tests, {len(tests) - len(todo)} already clean, {len(todo)} to run; "
          f"logs and {RESULTS} in {out}", flush=True)
    failed = run_all(todo, waits, fp, results, ledger, out, supp, shim, args.j, args.force)
    status = print_list(tests, prints, results, ledger, False)
    return 1 if failed else status


if __name__ == "__main__":
    sys.exit(main())
