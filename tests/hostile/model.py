"""Shared definitions of the hostile matrix: limits, what a case is, what it expects, what a run gave."""

import os
import re
from dataclasses import dataclass, field

import recipes as R

SANITIZE = os.environ.get("BAKE_SANITIZE") == "1"
# The ceilings of a case: 2 GiB and 30 s in a plain build. AddressSanitizer's redzones, shadow memory
# and quarantine of freed blocks roughly double a tool's resident memory and slow it several times,
# so under it the ceilings are 4 GiB of peak RSS and 120 s (the plain stage holds the real 2 GiB / 30 s).
MEM_LIMIT = (4 if SANITIZE else 2) << 30   # bytes: address space (RLIMIT_AS) or peak RSS
TIME_LIMIT = 30.0 * (4 if SANITIZE else 1)  # seconds: the run is killed after this

# ----------------------------------------------------------------------------------------------
# Results and specs


@dataclass
class Result:
    argv: list
    rc: int                   # exit status, or -SIGNAL
    timed_out: bool
    mem_killed: bool
    elapsed: float
    maxrss: int               # bytes
    stdout: bytes
    stderr: bytes
    mode: str                 # 'as' (RLIMIT_AS) or 'rss' (peak RSS measured)
    spawn_error: str = ""

    @property
    def err(self):
        return self.stderr.decode("utf-8", "replace")

    @property
    def out(self):
        return self.stdout.decode("utf-8", "replace")

    def first_err(self):
        lines = [l for l in self.err.splitlines() if l.strip()]
        for l in lines:
            if ": error:" in l:
                return l
        return lines[0] if lines else (self.spawn_error or "")


@dataclass
class Spec:
    """What a case runs and expects (built by the case inside its folder)."""
    tool: str
    args: list
    expect: tuple = (0,)
    frags: list = field(default_factory=list)     # groups checked on failure: each str, regex or tuple (any of)
    frags_stdout: bool = False                    # fragments may also be on stdout (bakeplay validate's verdicts)
    inputs: list = field(default_factory=list)    # must be byte-identical after any run
    outputs: list = field(default_factory=list)   # sentinel written; byte-identical after a failed run
    reports: list = field(default_factory=list)   # --report paths: a failed run may replace them with its
                                                  # failure report (formats/report.md), nothing else
    sentinel: bool = True                         # write sentinels at outputs that do not exist
    checks: list = field(default_factory=list)    # callables (ctx, spec, res) -> [problem]
    feeder: object = None                         # callable(stop_event) run in a thread during the run
    absent: list = field(default_factory=list)    # paths that must not exist after the run
    cwd: str = None
    timeout: float = None
    validate: list = field(default_factory=list)  # packages bakeplay validate must accept (after exit 0)
    env: dict = None
    dev_watch: bool = False                       # look for temporaries left in /dev
    note: str = ""


@dataclass
class Case:
    cls: str
    recipe: str      # recipe name (tool or tool-subcommand)
    name: str
    build: object    # callable(ctx) -> Spec
    idle: bool = False   # mostly waiting (FIFOs): runs in the wide pool
    phase: int = 0

    @property
    def id(self):
        return "%s/%s/%s" % (self.cls, self.recipe, self.name)

    @property
    def tool(self):
        return R.TOOL_OF.get(self.recipe, self.recipe)


@dataclass
class Outcome:
    case: Case
    problems: list
    args: list = None
    expect: tuple = ()
    rc: object = None
    first: str = ""
    elapsed: float = 0.0
    maxrss: int = 0
    extra: dict = field(default_factory=dict)


class Ctx:
    """What a case's build function and checks see."""

    def __init__(self, env, case, d):
        self.env = env
        self.case = case
        self.dir = d
        self.notes = []

    def shared(self, key, fn):
        return self.env.shared(key, fn)

    def shared_file(self, name, make, version="1"):
        return self.env.shared_file(name, make, version)

    def run_aux(self, tool, args, cwd=None, timeout=None):
        return self.env.run_tool(tool, args, cwd or self.dir, timeout=timeout, tag="aux")

    def path(self, *parts):
        return os.path.join(self.dir, *parts)



def match_fragment(frag, text):
    alts = frag if isinstance(frag, tuple) else (frag,)
    for a in alts:
        if isinstance(a, re.Pattern):
            if a.search(text):
                return True
        elif a in text:
            return True
    return False


def describe_fragment(frag):
    alts = frag if isinstance(frag, tuple) else (frag,)
    return " or ".join(repr(a.pattern) if isinstance(a, re.Pattern) else repr(a) for a in alts)


