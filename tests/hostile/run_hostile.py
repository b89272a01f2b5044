#!/usr/bin/env python3
"""The hostile-input matrix (CTest label `hostile`): every tool against hostile inputs and outputs,
class by class, generated from tables (classes.py). Each case runs one tool as a subprocess with a
time and a memory ceiling and checks its exit code, its message, that no temporary file is left, that
inputs (always) and earlier outputs (after a failure) are byte-identical, and the class's own checks.
See README.md. Python 3.11 standard library only."""

import argparse
import concurrent.futures
import errno
import fnmatch
import hashlib
import json
import os
import re
import resource
import shutil
import signal
import stat
import subprocess
import sys
import threading
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # nothing written into the source tree

import inputs as I  # noqa: E402
import recipes as R  # noqa: E402
from model import (SANITIZE, MEM_LIMIT, TIME_LIMIT, Result, Outcome, Ctx,  # noqa: E402
                   match_fragment, describe_fragment)

TOOLS = ["bakeinfo", "geobake", "bakeshape", "revolbake", "groovebake", "tambake", "strokebake", "bakeplay",
         "bakepipe"]
PROBE_RECIPE = {"bakeinfo": "bakeinfo", "geobake": "geobake", "bakeshape": "bakeshape", "revolbake": "revolbake",
                "groovebake": "groovebake", "tambake": "tambake", "strokebake": "strokebake",
                "bakeplay": "bakeplay-validate", "bakepipe": "bakepipe-assemble"}
DEVICES = {"/dev/null": (1, 3), "/dev/full": (1, 7), "/dev/zero": (1, 5), "/dev/urandom": (1, 9)}
SENTINEL = b"HOSTILE-SENTINEL: an earlier output that a failed run must leave as it is\n"


# ----------------------------------------------------------------------------------------------
# Running a tool


def read_rss(pid):
    total = 0
    pids = [pid]
    try:
        with open("/proc/%d/task/%d/children" % (pid, pid)) as f:
            pids += [int(x) for x in f.read().split()]
    except OSError:
        pass
    for p in pids:
        try:
            with open("/proc/%d/status" % p) as f:
                for line in f:
                    if line.startswith("VmRSS:"):
                        total += int(line.split()[1]) * 1024
                        break
        except OSError:
            pass
    return total


def _limit_as():
    resource.setrlimit(resource.RLIMIT_AS, (MEM_LIMIT, MEM_LIMIT))


def run_process(argv, cwd, mode, timeout, out_path, err_path, env=None):
    """Runs argv; kills its process group after `timeout` s, or (mode 'rss') when its RSS passes the
    ceiling. Returns a Result."""
    preexec = _limit_as if mode == "as" else None
    spawn_error = ""
    for attempt in range(13):
        try:
            with open(out_path, "wb") as fo, open(err_path, "wb") as fe:
                p = subprocess.Popen(argv, cwd=cwd, stdin=subprocess.DEVNULL, stdout=fo, stderr=fe,
                                     preexec_fn=preexec, start_new_session=True, env=env)
            break
        except OSError as e:
            # A binary being relinked (ETXTBSY) or briefly missing: wait and retry for a minute.
            if e.errno in (errno.ETXTBSY, errno.ENOENT, errno.EACCES) and attempt < 12 and os.path.isabs(argv[0]):
                time.sleep(5)
                continue
            spawn_error = "cannot start %s: %s" % (argv[0], e)
            return Result(argv, -1000, False, False, 0.0, 0, b"", spawn_error.encode(), mode, spawn_error)
    t0 = time.monotonic()
    state = {"timeout": False, "mem": False}
    done = threading.Event()

    def monitor():
        while not done.wait(0.05):
            if time.monotonic() - t0 > timeout:
                state["timeout"] = True
                _killpg(p.pid)
                return
            if mode == "rss" and read_rss(p.pid) > MEM_LIMIT:
                state["mem"] = True
                _killpg(p.pid)
                return

    th = threading.Thread(target=monitor, daemon=True)
    th.start()
    while True:
        try:
            _, status, ru = os.wait4(p.pid, 0)
            break
        except InterruptedError:
            continue
    elapsed = time.monotonic() - t0
    done.set()
    th.join()
    p.returncode = 0  # reaped here; keeps Popen from waiting again
    _killpg(p.pid)    # leftovers of the group (children of a tool)
    rc = -os.WTERMSIG(status) if os.WIFSIGNALED(status) else os.WEXITSTATUS(status)
    with open(out_path, "rb") as f:
        out = f.read()
    with open(err_path, "rb") as f:
        err = f.read()
    return Result(argv, rc, state["timeout"], state["mem"], elapsed, ru.ru_maxrss * 1024, out, err, mode)


def _killpg(pgid):
    try:
        os.killpg(pgid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


# ----------------------------------------------------------------------------------------------
# File snapshots


def digest(path, size):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        if size <= 64 << 20:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
        else:  # big shared inputs: the ends and the size
            h.update(f.read(4 << 20))
            f.seek(size - (4 << 20))
            h.update(f.read(4 << 20))
    return h.hexdigest()


def snapshot(path):
    """(link part, target part): what a path is, and for regular files their content hash."""
    try:
        lst = os.lstat(path)
    except OSError:
        return ("missing",)
    link = ("link", os.readlink(path)) if stat.S_ISLNK(lst.st_mode) else ("entry", stat.S_IFMT(lst.st_mode))
    try:
        st = os.stat(path)
    except OSError:
        return (link, "dangling")
    if stat.S_ISREG(st.st_mode):
        try:
            return (link, "file", st.st_size, digest(path, st.st_size))
        except OSError as e:
            return (link, "unreadable", str(e))
    return (link, "type", stat.S_IFMT(st.st_mode))


def is_regular(path):
    try:
        return stat.S_ISREG(os.stat(path).st_mode)
    except OSError:
        return False


def find_temporaries(root):
    found = []
    for dirpath, dirnames, filenames in os.walk(root):
        for n in filenames + dirnames:
            if fnmatch.fnmatch(n, "*.tmp.*"):
                found.append(os.path.join(dirpath, n))
    return found


def dev_temporaries():
    try:
        return {n for n in os.listdir("/dev") if fnmatch.fnmatch(n, "*.tmp.*")}
    except OSError:
        return set()


def check_devices(restore=True):
    """The system's device nodes are still character devices; a broken one is made again."""
    problems = []
    for path, (major, minor) in DEVICES.items():
        try:
            ok = stat.S_ISCHR(os.lstat(path).st_mode)
        except OSError:
            ok = False
        if not ok:
            problems.append("%s is no longer a character device" % path)
            if restore:
                try:
                    if os.path.lexists(path):
                        os.unlink(path)
                    os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(major, minor))
                    os.chmod(path, 0o666)
                except OSError as e:
                    problems.append("could not restore %s: %s" % (path, e))
    return problems


# ----------------------------------------------------------------------------------------------
# The environment shared by the cases of a run


class Env:
    def __init__(self, tools_dir, tmp, jobs):
        self.tools_dir = os.path.abspath(tools_dir)
        self.tmp = os.path.abspath(tmp)
        self.cache = os.path.join(self.tmp, "_cache")
        self.jobs = jobs
        self.full = False
        os.makedirs(self.cache, exist_ok=True)
        self.lock = threading.Lock()
        self.shared_locks = {}
        self.shared_values = {}
        self.modes = {}
        self.mode_notes = {}
        self.results = {}      # case id -> Outcome (for phase-1 cases)
        self.help_cache = {}
        self.missing = set()
        self.aux_count = 0

    def tool_path(self, tool):
        for cand in (os.path.join(self.tools_dir, tool, tool), os.path.join(self.tools_dir, tool)):
            if os.path.isfile(cand) and os.access(cand, os.X_OK):
                return cand
        return os.path.join(self.tools_dir, tool, tool)

    # Values made once per run (big inputs, baselines), whichever case asks first.
    def shared(self, key, fn):
        with self.lock:
            lk = self.shared_locks.setdefault(key, threading.Lock())
        with lk:
            if key not in self.shared_values:
                try:
                    self.shared_values[key] = ("ok", fn())
                except Exception as e:  # noqa: BLE001 - reported by every case that needs it
                    self.shared_values[key] = ("error", "%s: %s" % (type(e).__name__, e))
            kind, value = self.shared_values[key]
        if kind == "error":
            raise RuntimeError("shared input %s: %s" % (key, value))
        return value

    def shared_file(self, name, make, version="1"):
        """A file in the cache folder, made by make(path) once (kept across runs: the name and
        `version` say what it is). Classes run as parallel processes share the cache: a file is made
        under a name of this process and renamed into place, its stamp written last."""
        path = os.path.join(self.cache, name)

        def fn():
            stamp = path + ".done"
            if os.path.exists(path) and _read(stamp) == version:
                return path
            part = "%s.part-%d" % (path, os.getpid())
            for p in (part, part + ".work"):
                if os.path.lexists(p):
                    _rmtree(p) if os.path.isdir(p) and not os.path.islink(p) else os.unlink(p)
            make(part)
            os.replace(part, path)
            if os.path.isdir(part + ".work"):
                _rmtree(part + ".work")
            with open(stamp + ".part-%d" % os.getpid(), "w") as f:
                f.write(version)
            os.replace(stamp + ".part-%d" % os.getpid(), stamp)
            return path

        return self.shared("file:" + name, fn)

    def probe_modes(self):
        """RLIMIT_AS of 2 GiB unless a tool cannot start under it (then peak RSS is measured instead).
        Under BAKE_SANITIZE=1 (AddressSanitizer) never RLIMIT_AS."""
        probe_dir = os.path.join(self.tmp, "_probe", str(os.getpid()))
        os.makedirs(probe_dir, exist_ok=True)
        key_file = os.path.join(self.cache, "probe.json")
        key = {}
        for t in TOOLS:
            p = self.tool_path(t)
            try:
                st = os.stat(p)
                key[t] = [p, st.st_size, st.st_mtime_ns, SANITIZE]
            except OSError:
                key[t] = [p, None, None, SANITIZE]
        try:
            with open(key_file) as f:
                saved = json.load(f)
            if saved.get("key") == key:
                self.modes, self.mode_notes = saved["modes"], saved["notes"]
                return
        except (OSError, ValueError, KeyError):
            pass
        for t in TOOLS:
            p = self.tool_path(t)
            if SANITIZE:
                self.modes[t], self.mode_notes[t] = "rss", "BAKE_SANITIZE=1: peak RSS measured, no RLIMIT_AS"
                continue
            if not os.path.exists(p):
                self.modes[t], self.mode_notes[t] = "as", "missing"
                continue
            # --version, then a small run of the tool (the recipe's), under the ceiling; where one fails
            # there and succeeds without it, the ceiling itself breaks the tool: measure RSS instead.
            d = os.path.join(probe_dir, t)
            os.makedirs(d)
            inv = R.RECIPES[PROBE_RECIPE[t]](Ctx(self, None, d))
            notes = []
            mode = "as"
            for args in (["--version"], inv.args):
                res = run_process([p] + args, d, "as", 120, d + ".out", d + ".err")
                what = "--version" if args == ["--version"] else "a small run"
                notes.append("%s under RLIMIT_AS: exit %s, peak RSS %.0f MiB" % (what, res.rc, res.maxrss / 2**20))
                if res.rc != 0:
                    free = run_process([p] + args, d, "rss", 120, d + ".out", d + ".err")
                    notes.append("without it: exit %s" % free.rc)
                    if free.rc == 0:
                        mode = "rss"
                        break
            self.modes[t] = mode
            self.mode_notes[t] = "; ".join(notes)
        with open(key_file + ".part-%d" % os.getpid(), "w") as f:
            json.dump({"key": key, "modes": self.modes, "notes": self.mode_notes}, f)
        os.replace(key_file + ".part-%d" % os.getpid(), key_file)
        _rmtree(probe_dir)

    def wait_for_tool(self, tool):
        """A binary that is missing (or being written) is waited for, a minute at most, once."""
        with self.lock:
            lk = self.shared_locks.setdefault("tool:" + tool, threading.Lock())
        with lk:
            if tool in self.missing:
                return
            for _ in range(61):
                p = self.tool_path(tool)
                if os.path.isfile(p) and os.access(p, os.X_OK):
                    return
                time.sleep(1)
            self.missing.add(tool)

    def run_tool(self, tool, args, cwd, timeout=None, env=None, tag="run"):
        self.wait_for_tool(tool)
        p = self.tool_path(tool)
        if tool in self.missing:
            why = "cannot start %s: no such executable" % p
            return Result([p] + list(args), -1000, False, False, 0.0, 0, b"", why.encode(), "as", why)
        mode = self.modes.get(tool, "rss" if SANITIZE else "as")
        with self.lock:
            self.aux_count += 1
            n = self.aux_count
        base = os.path.join(os.path.dirname(cwd.rstrip("/")) or self.tmp, ".%s.%s.%d" % (
            os.path.basename(cwd.rstrip("/")), tag, n))
        res = run_process([p] + list(args), cwd, mode, timeout or TIME_LIMIT, base + ".stdout", base + ".stderr", env)
        for suffix in (".stdout", ".stderr"):
            try:
                os.unlink(base + suffix)
            except OSError:
                pass
        return res

    def help_text(self, tool, sub=None):
        key = (tool, sub)
        with self.lock:
            if key in self.help_cache:
                return self.help_cache[key]
        args = ([sub] if sub else []) + ["--help"]
        res = self.run_tool(tool, args, self.tmp, timeout=60, tag="help")
        with self.lock:
            self.help_cache[key] = res.out
        return res.out


# ----------------------------------------------------------------------------------------------
# One case


def safe_name(s):
    return re.sub(r"[^A-Za-z0-9_.-]", "_", s)[:120]


def execute(env, case):
    d = os.path.join(env.tmp, case.cls, safe_name(case.recipe), safe_name(case.name))
    if os.path.lexists(d):
        _rmtree(d)
    os.makedirs(d)
    ctx = Ctx(env, case, d)
    try:
        spec = case.build(ctx)
    except Exception as e:  # noqa: BLE001
        if isinstance(e, RuntimeError) and str(e).startswith("not run:"):
            return Outcome(case, [str(e)], rc="not run")
        tb = traceback.format_exc().strip().splitlines()
        return Outcome(case, ["setup failed: %s: %s (%s)" % (type(e).__name__, e, tb[-3].strip() if len(tb) > 2 else "")],
                       rc="not run")
    if spec is None:
        return None
    cwd = spec.cwd or d
    absolute = lambda p: p if os.path.isabs(p) else os.path.join(cwd, p)

    # Sentinels at outputs that do not exist (their folder does); snapshots of regular outputs.
    before_out = {}
    for p in spec.outputs:
        if not p:
            continue
        ap = absolute(p)
        if spec.sentinel and not os.path.lexists(ap) and os.path.isdir(os.path.dirname(ap)) and \
                ap.startswith(d + "/"):
            with open(ap, "wb") as f:
                f.write(SENTINEL + ap.encode("utf-8", "surrogateescape") + b"\n")
        if is_regular(ap):
            before_out[p] = snapshot(ap)
    before_in = {p: snapshot(absolute(p)) for p in spec.inputs if p}
    dev_before = dev_temporaries() if spec.dev_watch else set()

    stop = threading.Event()
    feeder = None
    if spec.feeder:
        feeder = threading.Thread(target=spec.feeder, args=(stop,), daemon=True)
        feeder.start()
    env_vars = None
    if spec.env:
        env_vars = dict(os.environ)
        for k, v in spec.env.items():
            if v is None:
                env_vars.pop(k, None)
            else:
                env_vars[k] = v
    timeout = spec.timeout or TIME_LIMIT
    if spec.timeout and SANITIZE:
        timeout = spec.timeout * 4
    res = env.run_tool(spec.tool, spec.args, cwd, timeout=timeout, env=env_vars)
    stop.set()
    if feeder:
        if hasattr(spec.feeder, "release"):
            spec.feeder.release()
        feeder.join(10)

    problems = []
    if res.spawn_error:
        problems.append(res.spawn_error)
    elif res.timed_out:
        problems.append("killed after the %.0f s ceiling (hang or far too slow)" % timeout)
    elif res.mem_killed:
        problems.append("killed: resident memory passed %d MiB" % (MEM_LIMIT >> 20))
    elif res.rc < 0:
        problems.append("died of signal %d (%s)" % (-res.rc, signal.Signals(-res.rc).name if -res.rc in
                                                     signal.valid_signals() else "?"))
    if res.mode == "rss" and res.maxrss > MEM_LIMIT and not res.mem_killed:
        problems.append("peak RSS %.0f MiB over the ceiling" % (res.maxrss / 2**20))
    ok_exit = res.rc in spec.expect
    if not res.spawn_error and not res.timed_out and not res.mem_killed and res.rc >= 0 and not ok_exit:
        problems.append("exit %d, expected %s" % (res.rc, " or ".join(map(str, spec.expect))))
    if res.rc == 4 and 4 not in spec.expect:
        problems.append("internal error (exit 4)")
    err = res.err
    messages = err + ("\n" + res.out if spec.frags_stdout else "")
    if res.rc > 0:
        prefix = "%s: error:" % spec.tool
        if prefix not in err:
            problems.append("stderr lacks %r" % prefix)
        if ok_exit:
            for frag in spec.frags:
                if not match_fragment(frag, messages):
                    problems.append("stderr lacks %s" % describe_fragment(frag))
    for p in find_temporaries(d):
        problems.append("temporary left: %s" % os.path.relpath(p, d))
    if spec.dev_watch:
        for n in dev_temporaries() - dev_before:
            problems.append("temporary left in /dev: %s" % n)
            try:
                os.unlink(os.path.join("/dev", n))
            except OSError:
                pass
    for p, snap in before_in.items():
        if snapshot(absolute(p)) != snap:
            problems.append("input changed: %s" % shorten_path(p, d))
    if res.rc != 0:
        others = {os.path.normpath(absolute(p)) for p in spec.outputs if p not in spec.reports}
        for p, snap in before_out.items():
            if snapshot(absolute(p)) == snap:
                continue
            if p in spec.reports and os.path.normpath(absolute(p)) not in others:
                # The run record is written also when the run fails (formats/report.md): it must
                # then be that failure's report.
                why = failure_report_problem(absolute(p), res.rc)
                if why:
                    problems.append("report %s replaced by %s" % (shorten_path(p, d), why))
                continue
            problems.append("earlier output changed by a failed run: %s" % shorten_path(p, d))
    for p in spec.absent:
        if os.path.lexists(absolute(p)):
            problems.append("written although it must not be: %s" % shorten_path(p, d))
    problems += check_devices()
    if not res.spawn_error and not res.timed_out and not res.mem_killed:
        for check in spec.checks:
            try:
                problems += list(check(ctx, spec, res) or [])
            except Exception as e:  # noqa: BLE001
                problems.append("check failed: %s: %s" % (type(e).__name__, e))
    out = Outcome(case, problems, args=[spec.tool] + list(spec.args), expect=spec.expect, rc=res.rc,
                  first=res.first_err(), elapsed=res.elapsed, maxrss=res.maxrss)
    out.extra["dir"] = d
    out.extra["note"] = " ".join(ctx.notes + ([spec.note] if spec.note else []))
    if res.rc == 0 and not problems and spec.validate:
        out.extra["validate"] = [absolute(p) for p in spec.validate]
    if res.timed_out:
        out.rc = "killed"
    elif res.spawn_error:
        out.rc = "not started"
    return out


def failure_report_problem(path, rc):
    try:
        with open(path, "rb") as f:
            doc = json.loads(f.read())
        code = doc["status"]["exitCode"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        return "something that is not a failure report (%s)" % type(e).__name__
    if code != rc:
        return "a report with exitCode %s (the run exited %s)" % (code, rc)
    return ""


def _read(path):
    try:
        with open(path) as f:
            return f.read()
    except OSError:
        return None


def _rmtree(d):
    def onerror(func, path, exc):
        try:
            os.chmod(path, 0o700)
            func(path)
        except OSError:
            pass
    shutil.rmtree(d, onerror=onerror)


def shorten_path(p, d):
    return p.replace(d + "/", "$D/").replace(d, "$D")


# ----------------------------------------------------------------------------------------------
# bakeplay validate, batched: packages of successful runs that must validate


def validate_batch(env, outcomes):
    want = []
    for o in outcomes:
        for p in o.extra.get("validate", []):
            want.append((o, p))
    if not want:
        return
    vdir = os.path.join(env.tmp, "_validate", outcomes[0].case.cls)
    if os.path.exists(vdir):
        _rmtree(vdir)
    os.makedirs(vdir)
    verdicts = {}   # content hash -> (ok, line)
    by_hash = {}
    for o, p in want:
        try:
            h = digest(p, os.path.getsize(p))
        except OSError as e:
            o.problems.append("package to validate missing: %s (%s)" % (shorten_path(p, o.extra["dir"]), e))
            continue
        if h not in by_hash:
            link = os.path.join(vdir, "p%04d.glb" % len(by_hash))
            shutil.copyfile(p, link)
            by_hash[h] = link
        o.extra.setdefault("hashes", []).append((p, h))

    def run_chunk(paths):
        res = env.run_tool("bakeplay", ["validate"] + paths + ["--size", "16"], vdir,
                           timeout=max(TIME_LIMIT, 10 * len(paths)), tag="validate")
        found = {}
        for line in res.out.splitlines() + res.err.splitlines():
            for p in paths:
                if p in line and p not in found and (line.startswith("PASS") or line.startswith("FAIL")):
                    found[p] = (line.startswith("PASS"), line.strip())
        return res, found

    items = list(by_hash.items())
    chunk = 24
    for k in range(0, len(items), chunk):
        part = items[k:k + chunk]
        paths = [p for _, p in part]
        res, found = run_chunk(paths)
        if res.rc < 0 or res.timed_out or len(found) < len(paths):
            for h, p in part:  # one at a time, to tell which package makes it fail
                r1, f1 = run_chunk([p])
                if p in f1:
                    verdicts[h] = f1[p]
                else:
                    verdicts[h] = (False, "bakeplay validate: exit %s, %s" % ("killed" if r1.timed_out else r1.rc,
                                                                             r1.first_err()[:100]))
        else:
            for h, p in part:
                verdicts[h] = found[p]
    print("bakeplay validate: %d packages (%d distinct) of %s" % (len(want), len(by_hash), outcomes[0].case.cls),
          flush=True)
    for o in outcomes:
        for p, h in o.extra.get("hashes", []):
            ok, line = verdicts.get(h, (False, "not validated"))
            if not ok:
                o.problems.append("bakeplay validate refuses %s: %s" % (os.path.basename(p), line[:160]))


# ----------------------------------------------------------------------------------------------
# Reporting


def short_args(args, d):
    text = " ".join(repr(a) if (not a or re.search(r"[\s'\"$\\#|:;]", a) or not a.isprintable()) else a
                    for a in args[1:])
    if d:
        text = text.replace(d + "/", "").replace(d, "$D")
    text = text.replace("\n", "\\n")
    return text if len(text) <= 150 else text[:147] + "..."


def print_report(outcomes, classes, env, elapsed):
    failed = [o for o in outcomes if o.problems]
    print()
    print("hostile: %d cases, %d failed, %.1f s" % (len(outcomes), len(failed), elapsed))
    print()
    per_class = {}
    for o in outcomes:
        c = per_class.setdefault(o.case.cls, {})
        t = c.setdefault(o.case.tool, [0, 0])
        t[0] += 1
        t[1] += bool(o.problems)
    print("%-16s %6s %6s  per tool (cases/failed)" % ("class", "cases", "failed"))
    for cls in classes:
        c = per_class.get(cls, {})
        n = sum(v[0] for v in c.values())
        f = sum(v[1] for v in c.values())
        tools = ", ".join("%s %d/%d" % (t, v[0], v[1]) for t, v in sorted(c.items()))
        print("%-16s %6d %6d  %s" % (cls, n, f, tools))
    if failed:
        print()
        print("FAILURES")
        rows = []
        for o in sorted(failed, key=lambda o: o.case.id):
            d = o.extra.get("dir", "")
            rows.append((o.case.id, short_args(o.args or [], d), "/".join(map(str, o.expect)), str(o.rc),
                         (o.first or "").replace("\n", "\\n")[:160], "; ".join(o.problems)[:400],
                         "%.1f s" % o.elapsed, o.extra.get("note", "")))
        for r in rows:
            print("- %s" % r[0])
            print("    args:     %s" % r[1])
            print("    expected: %-8s got: %-8s (%s)" % (r[2], r[3], r[6]))
            print("    stderr:   %s" % r[4])
            print("    problems: %s" % r[5])
            if r[7]:
                print("    note:     %s" % r[7])
    print()
    print("hostile: %d of %d cases failed" % (len(failed), len(outcomes)))


# ----------------------------------------------------------------------------------------------
# Main


def main():
    import classes as C  # noqa: E402 - after sys.path is set

    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--tools", required=True, help="the build's tools folder (TOOL/TOOL or TOOL inside)")
    ap.add_argument("--tmp", required=True, help="scratch folder (cases and cached big inputs)")
    ap.add_argument("--class", dest="classes", action="append", help="run only this class (repeatable)")
    ap.add_argument("--only", action="append", help="run only cases whose id contains this (repeatable)")
    ap.add_argument("--list", action="store_true", help="list the case ids and exit")
    ap.add_argument("-j", "--jobs", type=int, default=max(2, os.cpu_count() or 2),
                    help="cases run at once (cases that mostly wait on FIFOs run beside them)")
    ap.add_argument("--keep", action="store_true", help="keep the case folders of passing cases")
    ap.add_argument("--full", action="store_true",
                    help="the whole matrix (every variant on every tool and option) instead of the default "
                         "selection, which meets every variant on every tool in fewer runs")
    a = ap.parse_args()

    names = a.classes or list(C.CLASSES)
    for n in names:
        if n not in C.CLASSES:
            ap.error("unknown class %r (classes: %s)" % (n, ", ".join(C.CLASSES)))
    env = Env(a.tools, a.tmp, a.jobs)
    env.full = a.full
    cases = []
    for n in names:
        cases += C.CLASSES[n](env)
    seen = set()
    for c in cases:
        if c.id in seen:
            raise SystemExit("duplicate case id %s" % c.id)
        seen.add(c.id)
    if a.only:
        cases = [c for c in cases if any(s in c.id for s in a.only)]
    if a.list:
        for c in cases:
            print(c.id)
        print("%d cases" % len(cases), file=sys.stderr)
        return 0
    if not cases:
        print("hostile: no case selected")
        return 1
    t0 = time.monotonic()
    env.probe_modes()
    for t in TOOLS:
        if env.modes.get(t) == "rss":
            print("hostile: %s: memory ceiling as peak RSS (%s)" % (t, env.mode_notes.get(t, "")))
    outcomes = []
    print_lock = threading.Lock()

    def run_one(case):
        o = execute(env, case)
        if o is None:
            return None
        with env.lock:
            env.results[case.id] = o
        with print_lock:
            status = "FAIL" if o.problems else "ok"
            print("%-4s %s (exit %s, %.1f s)" % (status, case.id, o.rc, o.elapsed), flush=True)
        return o

    for phase in sorted({c.phase for c in cases}):
        batch = [c for c in cases if c.phase == phase]
        with concurrent.futures.ThreadPoolExecutor(a.jobs) as cpu, \
                concurrent.futures.ThreadPoolExecutor(8) as wide:
            futures = [(wide if c.idle else cpu).submit(run_one, c) for c in batch]
            for f in futures:
                o = f.result()
                if o is not None:
                    outcomes.append(o)
    for cls in names:
        validate_batch(env, [o for o in outcomes if o.case.cls == cls])
    if not a.keep:
        for o in outcomes:
            if not o.problems and o.extra.get("dir") and os.path.isdir(o.extra["dir"]):
                _rmtree(o.extra["dir"])
    print_report(outcomes, names, env, time.monotonic() - t0)
    return 1 if any(o.problems for o in outcomes) else 0


if __name__ == "__main__":
    sys.exit(main())
