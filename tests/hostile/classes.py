"""The hostile classes: each function builds the cases of one class from tables (tools x slots x
variants). A case's build(ctx) prepares its folder and returns a Spec (run_hostile.py)."""

import json
import os
import re
import select
import shutil
import stat
import struct
import subprocess
import time

import inputs as I
import recipes as R
from model import Case, Ctx, Spec, match_fragment, describe_fragment

NINJA = shutil.which("ninja") or "/usr/bin/ninja"
MAKE = shutil.which("make") or "/usr/bin/make"
ZSTD = shutil.which("zstd") or ("/usr/bin/zstd" if os.path.exists("/usr/bin/zstd") else None)

MESH_EXTS = ("obj", "ply", "off", "stl", "glb", "gltf")


# ----------------------------------------------------------------------------------------------
# Helpers


def spec_of(inv, expect=(0,), frags=(), **kw):
    return Spec(tool=inv.tool, args=list(inv.args), expect=tuple(expect), frags=list(frags),
                inputs=[p for p in inv.inputs.values() if p], outputs=[p for p in inv.outputs.values() if p],
                reports=[inv.outputs["--report"]] if inv.outputs.get("--report") else [], cwd=inv.cwd,
                frags_stdout=inv.recipe == "bakeplay-validate", **kw)


def extra_for(recipe, slot, ext):
    """Options an input kind needs: strokebake grows few strokes on a mesh input."""
    if recipe == "strokebake" and slot == "strokes" and ext in MESH_EXTS:
        return ["--count", "20", "--points", "3"]
    return []


def mesh_for(recipe, slot):
    """The mesh of an input slot: a surface of revolution for revolbake's profile, else a tetrahedron."""
    return I.lathe(12) if (recipe == "revolbake" and slot == "profile") else I.tetra()


def tetra_glb(ctx):
    return ctx.shared_file("tetra.glb", lambda p: I.write(p, I.glb_of(I.tetra())))


def small_ktx2():
    """A small honest KTX2 (R8 16 x 16, one layer, one level, Zstandard RLE frame)."""
    return I.ktx2_bytes(16, 16, 0, 9, 1, [(I.zstd_rle_frame(256), 256)])


def valid_content(ctx, recipe, slot, ext, ref_names=None):
    """Bytes of a small valid input for a slot of a recipe, of the given kind (extension). Files it
    names (an SVG, a ring profile) are written beside it in the case folder."""
    ref_names = ref_names or {}
    mesh = mesh_for(recipe, slot)
    if recipe == "groovebake" and slot == "mesh" and ext == "obj":
        return I.obj_text_uv(mesh).encode()
    if ext in ("obj", "ply", "off", "stl"):
        return I.MESH_TEXT[ext](mesh).encode()
    if ext == "glb":
        if recipe == "bakepipe-assemble":
            with open(R.ring_package(ctx), "rb") as f:
                return f.read()
        return I.glb_of(mesh)
    if ext == "gltf":
        return I.gltf_data_uri(mesh).encode()
    if ext == "ktx2":
        return small_ktx2()
    if ext == "png":
        return {"profile": lambda: I.png_profile(64, 64), "height": lambda: I.png_pattern(16, 16),
                "colour": lambda: I.png_pattern(8, 8, 2), "image": lambda: I.png_pattern(16, 4)}[slot]()
    if ext == "svg":
        return (I.SVG_PROFILE if recipe == "revolbake" else I.SVG_DRAWING).encode()
    if ext == "csv":
        return (I.CSV_PROFILE if recipe == "revolbake" else I.STROKES_CSV).encode()
    if ext == "json":
        if recipe == "geobake":
            doc = I.SOURCES
        elif recipe == "revolbake":
            doc = I.RING_PROFILE
        elif recipe == "groovebake":
            svg = ref_names.get("svg", "drawing.svg")
            if not os.path.exists(ctx.path(svg)):
                I.write(ctx.path(svg), I.SVG_DRAWING)
            doc = I.groove_scene(svg)
        elif recipe == "tambake":
            doc = I.TAM_STYLE
        elif recipe == "strokebake":
            doc = I.STROKES
        elif recipe.startswith("bakepipe"):
            if slot == "input":
                doc = I.RING_PROFILE
            else:
                ring = ref_names.get("input", "ring.json")
                if not os.path.exists(ctx.path(ring)):
                    I.write(ctx.path(ring), I.RING_PROFILE)
                doc = I.pipe_scene(ring)
        else:
            raise ValueError("no JSON input for %s" % recipe)
        return json.dumps(doc, indent=1).encode()
    raise ValueError("no content for %s %s .%s" % (recipe, slot, ext))


def slot_default_path(ctx, recipe, slot, ext, stem=None):
    """Where a slot's replacement lives: the assembled packages' folder for bakepipe assemble, else
    the case folder."""
    if recipe == "bakepipe-assemble" and slot == "pkg":
        os.makedirs(ctx.path("baked"), exist_ok=True)
        return ctx.path("baked", "ring.revolution.glb")
    return ctx.path("%s.%s" % (stem or ("in_" + slot), ext))


def invoke(ctx, recipe, inp=None, out=None, use=(), extra=()):
    return R.RECIPES[recipe](ctx, inp=inp or {}, out=out, use=use, extra=list(extra))


def any_of(*alts):
    return tuple(a for a in alts if a)


def stderr_when(rc, *frags):
    """On exit `rc`, stderr must contain each fragment group."""
    def check(ctx, spec, res):
        if res.rc != rc:
            return []
        text = res.err + ("\n" + res.out if spec.frags_stdout else "")
        return ["stderr lacks %s" % describe_fragment(f) for f in frags if not match_fragment(f, text)]
    return check


def drain_fifo(path):
    """A reader that holds an output FIFO open and drains it (a tool that writes into it finishes)."""
    def run(stop):
        try:
            fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
        except OSError:
            return
        try:
            while not stop.is_set():
                r, _, _ = select.select([fd], [], [], 0.05)
                if r:
                    try:
                        if not os.read(fd, 1 << 16):
                            time.sleep(0.02)
                    except BlockingIOError:
                        pass
        finally:
            os.close(fd)
    return run


class feed_fifo:
    """A writer for an input FIFO, like `cat input > fifo &`: its open blocks until the tool opens the
    FIFO for reading; it then writes `data` and closes. After the run, release() unblocks a writer whose
    FIFO the tool never opened."""

    def __init__(self, path, data):
        self.path, self.data = path, data

    def __call__(self, stop):
        try:
            fd = os.open(self.path, os.O_WRONLY)
        except OSError:
            return
        try:
            if stop.is_set():
                return
            view = memoryview(self.data)
            while view:
                n = os.write(fd, view[:1 << 16])
                view = view[n:]
        except OSError:
            pass
        finally:
            os.close(fd)

    def release(self):
        try:
            fd = os.open(self.path, os.O_RDONLY | os.O_NONBLOCK)
            time.sleep(0.05)
            os.close(fd)
        except OSError:
            pass


def is_type(path, test):
    try:
        return test(os.lstat(path).st_mode)
    except OSError:
        return False


# ----------------------------------------------------------------------------------------------
# 1. ninja: bakepipe ninja with odd characters in paths

NINJA_CHARS = [("newline", "\n"), ("dollar", "$"), ("space", " "), ("colon", ":"), ("pipe", "|"), ("hash", "#")]
INJECTION = "\nbuild hostile_injected: phony\nrule hostile_rule\n  command = touch CANARY\nbuild CANARY: hostile_rule\n"
NINJA_TOKENS = {"scene": "scenefile.json", "input": "inputfile.json", "outdir": "outdirname", "output": "ninjafile"}


def ninja_tool(ctx, args, cwd):
    r = subprocess.run([NINJA] + args, cwd=cwd, capture_output=True, timeout=30)
    return r.returncode, r.stdout.decode("utf-8", "replace") + r.stderr.decode("utf-8", "replace")


def ninja_case(position, label, chars):
    def build(ctx):
        d = ctx.dir
        odd = "odd" + chars + NINJA_TOKENS[position]
        scene = ctx.path(odd) if position == "scene" else ctx.path("scene.json")
        ring = ctx.path(odd) if position == "input" else ctx.path("ring.json")
        outdir = ctx.path(odd) if position == "outdir" else ctx.path("baked")
        ninja_file = ctx.path(odd) if position == "output" else ctx.path("build.ninja")
        I.write(ring, I.RING_PROFILE)
        I.write(scene, I.pipe_scene(os.path.basename(ring)))
        args = ["ninja", scene, "-o", ninja_file, "--out-dir", outdir]
        expect = (1,) if "\n" in chars else (0, 1)

        def check(ctx, spec, res):
            problems = []
            if res.rc != 0:
                return problems
            if not os.path.isfile(ninja_file):
                return ["exit 0 but no Ninja file"]
            rc, text = ninja_tool(ctx, ["-n", "-f", ninja_file], d)
            if rc != 0:
                problems.append("ninja -n -f refuses the file (exit %d): %s" % (rc, text.strip().splitlines()[-1:]))
            for what, args_, bad in (("targets", ["-t", "targets", "all"], "hostile_injected"),
                                     ("rules", ["-t", "rules"], "hostile_rule"),
                                     ("commands", ["-t", "commands"], "touch CANARY")):
                rc, text = ninja_tool(ctx, ["-f", ninja_file] + args_, d)
                if bad in text:
                    problems.append("injected %s: ninja -t %s shows %r" % (what, args_[1], bad))
            package = os.path.join(outdir, "ring.revolution.glb")
            rc, text = ninja_tool(ctx, ["-f", ninja_file, "-t", "query", package], d)
            if rc != 0:
                problems.append("ninja knows no target %r (the out-dir path was not kept)" % package)
            elif position == "input" and ring not in [l.strip() for l in text.splitlines()]:
                problems.append("the bake of the ring does not list its input %r" % ring)
            if position in ("scene", "output"):
                rc, text = ninja_tool(ctx, ["-f", ninja_file, "-t", "query", ninja_file], d)
                if rc != 0:
                    problems.append("ninja knows no regenerate target %r" % ninja_file)
                elif scene not in [l.strip() for l in text.splitlines()]:
                    problems.append("the regenerate edge does not list the scene %r" % scene)
            for root in (d, os.path.dirname(ninja_file)):
                if os.path.exists(os.path.join(root, "CANARY")):
                    problems.append("the injected command ran (CANARY exists)")
            return problems

        return Spec(tool="bakepipe", args=args, expect=expect, frags=[NINJA_TOKENS[position].split(".")[0]],
                    inputs=[scene, ring], outputs=[ninja_file], checks=[check],
                    note="token %r must appear in the message" % NINJA_TOKENS[position].split(".")[0])
    return Case("ninja", "bakepipe-ninja", "%s-%s" % (position, label), build)


def class_ninja(env):
    cases = []
    for position in ("scene", "input", "outdir", "output"):
        for label, c in NINJA_CHARS:
            cases.append(ninja_case(position, label, c))
        cases.append(ninja_case(position, "injection", INJECTION))
        if env.full or position in ("input", "outdir"):
            cases.append(ninja_case(position, "dollar-variable", "$out${in}$$x"))
            cases.append(ninja_case(position, "pipes", " | implicit || order "))
    return cases


# ----------------------------------------------------------------------------------------------
# 2. aliasing outputs

SPELLINGS = ["same", "dot", "dotdot", "hardlink", "symlink"]


def spell(ctx, path, how):
    """Another name for `path`: (the name to pass, the cwd to run in)."""
    d = ctx.dir
    rel = os.path.relpath(path, d)
    if how == "same":
        return path, None
    if how == "dot":
        return "./" + rel, d
    if how == "dotdot":
        os.makedirs(ctx.path("sub"), exist_ok=True)
        return os.path.join(d, "sub", "..", rel), None
    if how == "hardlink":
        link = ctx.path("hl_" + os.path.basename(path))
        os.link(path, link)
        return link, None
    if how == "symlink":
        link = ctx.path("sl_" + os.path.basename(path))
        os.symlink(path, link)
        return link, None
    raise ValueError(how)


def alias_input_case(recipe, opt, slot, how):
    def build(ctx):
        use = (slot,)
        base = invoke(ctx, recipe, use=use)
        target = base.inputs[slot]
        name, cwd = spell(ctx, target, how)
        inv = invoke(ctx, recipe, inp=dict(base.inputs), out={opt: name}, use=use)
        inv.cwd = cwd
        spec = spec_of(inv, (1,), [any_of(os.path.basename(name), os.path.basename(target))])
        spec.inputs = [p for p in base.inputs.values()]
        return spec
    return Case("aliasing", recipe, "%s=input:%s/%s" % (opt.lstrip("-"), slot, how), build)


def alias_outputs_case(recipe, o1, o2, how):
    def build(ctx):
        base = invoke(ctx, recipe)
        first = base.outputs[o1]
        if how == "same":
            second = first
        elif how == "dotdot":
            os.makedirs(ctx.path("sub"), exist_ok=True)
            second = os.path.join(ctx.dir, "sub", "..", os.path.relpath(first, ctx.dir))
        else:  # a symbolic link to the first output (written as a sentinel before the run)
            second = ctx.path("sl_" + os.path.basename(first))
            os.symlink(first, second)
        inv = invoke(ctx, recipe, inp=dict(base.inputs), out={o1: first, o2: second})
        return spec_of(inv, (1,), [any_of(os.path.basename(first), os.path.basename(second))])
    return Case("aliasing", recipe, "%s=%s/%s" % (o2.lstrip("-"), o1.lstrip("-"), how), build)


def class_aliasing(env):
    """Default: each output option of each tool names one of its inputs, each input slot is named by
    one output, and the five spellings rotate so that each tool meets all of them (--full: every
    spelling of every output against every input). Outputs against each other: -o with each other
    output, the spellings rotating (--full: every pair, three spellings each)."""
    cases = []
    for recipe in R.WRITERS:
        outs = R.OUTPUTS[recipe]
        slots = list(R.SLOTS[recipe])
        if env.full:
            chosen = [(opt, slot, how) for opt in outs for slot in slots for how in SPELLINGS]
        elif slots:
            n = max(len(outs), len(slots), len(SPELLINGS))
            chosen = [(outs[k % len(outs)], slots[k % len(slots)], SPELLINGS[k % len(SPELLINGS)]) for k in range(n)]
        else:
            chosen = []
        cases += [alias_input_case(recipe, opt, slot, how) for opt, slot, how in chosen]
        out_pairs = [(o1, o2) for i, o1 in enumerate(outs) for o2 in outs[i + 1:]]
        spellings = ("same", "dotdot", "symlink")
        if env.full:
            chosen = [(o1, o2, how) for o1, o2 in out_pairs for how in spellings]
        else:
            chosen = [(o1, o2, spellings[k % 3]) for k, (o1, o2) in enumerate(p for p in out_pairs if p[0] == "-o")]
        cases += [alias_outputs_case(recipe, o1, o2, how) for o1, o2, how in chosen]
    return cases


# ----------------------------------------------------------------------------------------------
# 3. non-regular output targets

NODE_OF = {"/dev/null": (1, 3), "/dev/full": (1, 7)}


def out_ext(recipe, opt):
    if opt == "-o":
        return R.MAIN_OUT_EXT[recipe]
    return os.path.splitext(R.OUT_NAMES[opt])[1] or ".d"


def nonreg_case(recipe, opt, target):
    def build(ctx):
        d = ctx.dir
        checks = []
        feeder = None
        ext = out_ext(recipe, opt)
        if target in ("devnull-node", "devfull-node"):
            dev = "/dev/null" if target == "devnull-node" else "/dev/full"
            path = ctx.path(target + ext)
            os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(*NODE_OF[dev]))
            checks.append(lambda c, s, r: [] if is_type(path, stat.S_ISCHR) else
                          ["the character device node %s was replaced" % os.path.basename(path)])
        elif target == "fifo":
            path = ctx.path("fifo" + ext)
            os.mkfifo(path)
            feeder = drain_fifo(path)
            checks.append(lambda c, s, r: [] if is_type(path, stat.S_ISFIFO) else ["the FIFO was replaced"])
        else:  # the system's own /dev/null or /dev/full: only once the same run on a node was safe
            companion = "nonregular-out/%s/%s=%s" % (recipe, opt.lstrip("-"),
                                                     "devnull-node" if target == "/dev/null" else "devfull-node")
            prior = ctx.env.results.get(companion)
            if prior is None or any("was replaced" in p or "temporary left" in p for p in prior.problems):
                raise RuntimeError("not run: the same output as a character device in the case folder (%s) "
                                   "was replaced or left a temporary; running it on %s could break the system's "
                                   "device" % (companion.split("/")[-1], target))
            path = target
        inv = invoke(ctx, recipe, out={opt: path})
        spec = spec_of(inv, (2,), ["not a regular file"], checks=checks, feeder=feeder)
        spec.outputs = [p for p in spec.outputs if p != path]
        spec.dev_watch = path.startswith("/dev/")
        return spec
    label = {"/dev/null": "dev-null", "/dev/full": "dev-full"}.get(target, target)
    return Case("nonregular-out", recipe, "%s=%s" % (opt.lstrip("-"), label), build,
                phase=1 if target.startswith("/dev/") else 0)


# The default selection: -o /dev/null and a FIFO, --report /dev/null, --depfile /dev/full, a FIFO for
# the other outputs; each system device after the same run on a device node made in the case folder.
REDUCED_TARGETS = {"-o": ("devnull-node", "/dev/null", "fifo"), "--report": ("devnull-node", "/dev/null"),
                   "--depfile": ("devfull-node", "/dev/full")}


def class_nonregular_out(env):
    cases = []
    for recipe in R.WRITERS:
        for opt in R.OUTPUTS[recipe]:
            targets = ("devnull-node", "devfull-node", "fifo", "/dev/null", "/dev/full") if env.full else \
                REDUCED_TARGETS.get(opt, ("fifo",))
            for target in targets:
                cases.append(nonreg_case(recipe, opt, target))
    return cases


# ----------------------------------------------------------------------------------------------
# 4. recursion: deep node chains and deeply nested JSON

CHAIN = 100000
NEST = 100000
DEPTH_WORDS = any_of("depth", "deep", "nest")

# (recipe, slot, ext): the tools that read glTF scenes, through each of their glTF inputs.
GLTF_READERS = [("bakeinfo", "file", "glb"), ("bakeinfo", "file", "gltf"), ("geobake", "mesh", "glb"),
                ("geobake", "mesh", "gltf"), ("revolbake", "profile", "glb"), ("tambake", "mesh", "glb"),
                ("strokebake", "strokes", "glb"), ("strokebake", "growmesh", "glb"),
                ("bakeplay-validate", "pkg", "glb"), ("bakeplay-validate", "pkg", "gltf"),
                ("bakeplay-render", "pkg", "glb")]

# (recipe, slot, key): JSON inputs, and the key whose value becomes the nesting.
JSON_INPUTS = [("geobake", "sources", "fields"), ("revolbake", "profile", "contours"),
               ("groovebake", "scene", "grooves"), ("tambake", "style", "stroke"),
               ("strokebake", "strokes", "strokes"), ("bakepipe-plan", "scene", "objects"),
               ("bakepipe-ninja", "scene", "objects"), ("bakepipe-assemble", "scene", "objects")]


def chain_file(ctx, ext):
    mesh = I.lathe(12)
    if ext == "glb":
        return ctx.shared_file("chain%d.glb" % CHAIN, lambda p: I.write(p, I.chain_glb(mesh, CHAIN)))
    return ctx.shared_file("chain%d.gltf" % CHAIN, lambda p: I.write(p, I.chain_gltf(mesh, CHAIN)))


def place(ctx, src, dst):
    """A shared input in the case folder: a hard link (no copy; the input check sees any change)."""
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    try:
        os.link(src, dst)
    except OSError:
        shutil.copyfile(src, dst)
    return dst


def chain_case(recipe, slot, ext):
    def build(ctx):
        path = place(ctx, chain_file(ctx, ext), slot_default_path(ctx, recipe, slot, ext, "chain"))
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra_for(recipe, slot, ext))
        return spec_of(inv, (0, 3), checks=[stderr_when(3, DEPTH_WORDS)])
    return Case("recursion", recipe, "chain-%s:%s" % (slot, ext), build)


def nested_json_case(recipe, slot, key, kind):
    def build(ctx):
        doc = json.loads(valid_content(ctx, recipe, slot, "json"))
        doc[key] = "@@NEST@@"
        text = json.dumps(doc).replace('"@@NEST@@"', I.nested(NEST, kind), 1)
        path = I.write(ctx.path("nested.json"), text)
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,))
        return spec_of(inv, (3,), ["nest"])
    return Case("recursion", recipe, "nested-%s:%s-%s" % (slot, key, kind), build)


def nested_glb_case(recipe, slot, kind):
    def build(ctx):
        ext = "glb"
        mesh = mesh_for(recipe, slot)
        path = I.write(slot_default_path(ctx, recipe, slot, ext, "nested"), I.nested_ext_glb(mesh, NEST, kind))
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra_for(recipe, slot, ext))
        return spec_of(inv, (3,), ["nest"])
    return Case("recursion", recipe, "nested-BAKE-ext-%s:glb-%s" % (slot, kind), build)


def nested_svg_case(recipe, slot):
    def build(ctx):
        depth = NEST
        if recipe == "revolbake":
            body = '<path d="M 0 0 L 0.4 0 L 0.4 -0.8 L 0 -0.8 Z"/>'
        else:
            body = '<line x1="1" y1="5" x2="9" y2="5"/>'
        text = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">' + "<g>" * depth + body + \
               "</g>" * depth + "</svg>\n"
        path = I.write(ctx.path("nested.svg"), text)
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,))
        # A reader that builds no tree of the elements has nothing to recurse on: exit 0 is fine.
        return spec_of(inv, (0, 3), checks=[stderr_when(3, DEPTH_WORDS)])
    return Case("recursion", recipe, "nested-svg-%s" % slot, build)


def class_recursion(env):
    cases = [chain_case(*r) for r in GLTF_READERS]
    kinds = ("array", "object")
    for k, (recipe, slot, key) in enumerate(JSON_INPUTS):
        for kind in kinds if env.full else (kinds[k % 2],):
            cases.append(nested_json_case(recipe, slot, key, kind))
    for k, (recipe, slot, ext) in enumerate(r for r in GLTF_READERS if r[2] == "glb" and r[1] != "growmesh"):
        for kind in kinds if env.full else (kinds[k % 2],):
            cases.append(nested_glb_case(recipe, slot, kind))
    cases.append(nested_svg_case("groovebake", "svg"))
    cases.append(nested_svg_case("revolbake", "profile"))
    return cases


# ----------------------------------------------------------------------------------------------
# 5. non-regular inputs

# (recipe, slot, ext): every input kind of every tool.
INPUT_KINDS = [
    ("geobake", "mesh", "obj"), ("geobake", "sources", "json"),
    ("revolbake", "profile", "json"), ("revolbake", "profile", "csv"), ("revolbake", "profile", "svg"),
    ("revolbake", "profile", "png"), ("revolbake", "profile", "obj"), ("revolbake", "height", "png"),
    ("revolbake", "colour", "png"),
    ("groovebake", "scene", "json"), ("groovebake", "svg", "svg"), ("groovebake", "mesh", "obj"),
    ("tambake", "style", "json"), ("tambake", "mesh", "obj"), ("tambake", "image", "png"),
    ("strokebake", "strokes", "json"), ("strokebake", "strokes", "csv"), ("strokebake", "strokes", "obj"),
    ("strokebake", "growmesh", "obj"),
    ("bakeplay-validate", "pkg", "glb"), ("bakeplay-render", "pkg", "glb"),
    ("bakepipe-plan", "scene", "json"), ("bakepipe-ninja", "scene", "json"), ("bakepipe-assemble", "scene", "json"),
    ("bakepipe-assemble", "pkg", "glb"),
    ("bakeinfo", "file", "glb"), ("bakeinfo", "file", "ktx2"),
]
# glTF readers whose buffer URI can point at a device.
GLTF_URI_READERS = [("bakeinfo", "file"), ("geobake", "mesh"), ("revolbake", "profile"), ("tambake", "mesh"),
                    ("strokebake", "strokes"), ("bakeplay-validate", "pkg")]


def nonreg_in_case(recipe, slot, ext, variant):
    def build(ctx):
        path = slot_default_path(ctx, recipe, slot, ext, variant)
        feeder = None
        expect = (2,)
        frags = []
        if variant in ("dev-zero", "dev-urandom"):
            os.symlink("/dev/zero" if variant == "dev-zero" else "/dev/urandom", path)
            frags = [os.path.basename(path)]
        elif variant == "fifo-nowriter":
            os.mkfifo(path)
            expect = (1, 2, 3, 5)
        elif variant == "fifo-fed":
            os.mkfifo(path)
            feeder = feed_fifo(path, valid_content(ctx, recipe, slot, ext))
            expect = (0,)
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra_for(recipe, slot, ext))
        spec = spec_of(inv, expect, frags, feeder=feeder)
        if variant.startswith("fifo"):
            spec.checks.append(lambda c, s, r: [] if is_type(path, stat.S_ISFIFO) else ["the FIFO was replaced"])
        return spec
    return Case("nonregular-in", recipe, "%s:%s=%s" % (slot, ext, variant), build,
                idle=variant.startswith("fifo"))


def literal_dev_case(recipe, slot, dev, extra):
    def build(ctx):
        inv = invoke(ctx, recipe, inp={slot: dev}, use=(slot,), extra=extra)
        spec = spec_of(inv, (2,), [dev])
        spec.inputs = [p for p in spec.inputs if p != dev]
        return spec
    return Case("nonregular-in", recipe, "%s=%s" % (slot, dev.replace("/", "_").strip("_")), build)


def gltf_uri_dev_case(recipe, slot, dev):
    def build(ctx):
        mesh = mesh_for(recipe, slot)
        os.symlink(dev, ctx.path("buffer.bin"))
        doc, data = I.gltf_doc(mesh, uri="buffer.bin")
        path = I.write(ctx.path("model.gltf"), doc)
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra_for(recipe, slot, "gltf"))
        # A link from inside the folder to a device: refused either as leading outside the .gltf's
        # folder (URI confinement, 3) or as a device (2); never read.
        return spec_of(inv, (2, 3), ["buffer.bin"])
    return Case("nonregular-in", recipe, "%s:gltf-buffer-uri=%s" % (slot, dev.replace("/", "_").strip("_")), build)


def class_nonregular_in(env):
    """Default: every input kind gets one device (alternating /dev/zero and /dev/urandom) and one FIFO
    (alternating no writer and fed); the first input kind of each tool gets all four. --full: all four
    for every kind."""
    cases = []
    first = set()
    variants = ("dev-zero", "dev-urandom", "fifo-nowriter", "fifo-fed")
    for k, (recipe, slot, ext) in enumerate(INPUT_KINDS):
        if env.full or recipe not in first:
            chosen = variants
        else:
            chosen = (variants[k % 2], variants[2 + (k // 2) % 2])
        first.add(recipe)
        for variant in chosen:
            cases.append(nonreg_in_case(recipe, slot, ext, variant))
    for k, (recipe, slot) in enumerate(GLTF_URI_READERS):
        for dev in ("/dev/zero", "/dev/urandom") if env.full else (("/dev/zero", "/dev/urandom")[k % 2],):
            cases.append(gltf_uri_dev_case(recipe, slot, dev))
    for dev in ("/dev/zero", "/dev/urandom"):
        cases.append(literal_dev_case("bakeinfo", "file", dev, []))
        cases.append(literal_dev_case("revolbake", "profile", dev, ["--input-kind", "json"]))
    return cases


# ----------------------------------------------------------------------------------------------
# 6. decompression bombs: KTX2 levels that inflate past 1 GiB

BOMB_SIDE = 16384
BOMB_LAYERS = 8   # R8 16384 x 16384 x 8 = 2 GiB in the base level


def bomb_levels(side, layers, texel, content_size=True, levels=None):
    n = levels or 1
    out = []
    for i in range(n):
        s = max(1, side >> i)
        size = s * s * max(1, layers) * texel
        out.append((I.zstd_rle_frame(size, content_size=content_size), size))
    return out


def bomb_file(ctx, variant):
    def make(path):
        if variant == "rle-fcs":
            data = I.ktx2_bytes(BOMB_SIDE, BOMB_SIDE, BOMB_LAYERS, 9, 1, bomb_levels(BOMB_SIDE, BOMB_LAYERS, 1))
        elif variant == "rle-nofcs":
            data = I.ktx2_bytes(BOMB_SIDE, BOMB_SIDE, BOMB_LAYERS, 9, 1,
                                bomb_levels(BOMB_SIDE, BOMB_LAYERS, 1, content_size=False))
        elif variant == "full-chain":
            data = I.ktx2_bytes(BOMB_SIDE, BOMB_SIDE, BOMB_LAYERS, 9, 1, bomb_levels(BOMB_SIDE, BOMB_LAYERS, 1, levels=15))
        elif variant == "side":
            data = I.ktx2_bytes(32768, 32768, 0, 16, 2, bomb_levels(32768, 0, 2))
        elif variant == "zstd-cli":
            size = BOMB_SIDE * BOMB_SIDE * 5
            p = subprocess.Popen([ZSTD, "-3", "-q", "-c"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
            import threading
            chunks = []
            reader = threading.Thread(target=lambda: chunks.append(p.stdout.read()))
            reader.start()
            zero = bytes(1 << 22)
            left = size
            while left:
                n = min(left, len(zero))
                p.stdin.write(zero[:n])
                left -= n
            p.stdin.close()
            reader.join()
            p.wait()
            if p.returncode != 0:
                raise RuntimeError("zstd failed")
            data = I.ktx2_bytes(BOMB_SIDE, BOMB_SIDE, 5, 9, 1, [(chunks[0], size)])
        elif variant == "control":
            data = small_ktx2()
        else:
            raise ValueError(variant)
        I.write(path, data)
    return ctx.shared_file("bomb-%s.ktx2" % variant, make, version="2")


def tam_bomb_package(ctx, bomb):
    """A tambake package (8 tones applied to a tetrahedron) whose embedded TAM is replaced by `bomb`
    bytes: the base level of 16384 x 16384 x 8 layers inflates to 2 GiB."""
    def make(path):
        work = path + ".work"
        os.makedirs(work, exist_ok=True)
        style = dict(I.TAM_STYLE, tones=8)
        I.write(os.path.join(work, "style.json"), style)
        I.write(os.path.join(work, "mesh.obj"), I.obj_text(I.tetra()))
        res = ctx.run_aux("tambake", [os.path.join(work, "style.json"), "-o", os.path.join(work, "t.ktx2"),
                                      "--apply-to", os.path.join(work, "mesh.obj"), "--package",
                                      os.path.join(work, "pkg.glb"), "-q"], cwd=work)
        if res.rc != 0:
            raise RuntimeError("setup: tambake failed: " + res.first_err())
        with open(os.path.join(work, "pkg.glb"), "rb") as f:
            glb = f.read()
        if bomb is None:
            shutil.copyfile(os.path.join(work, "pkg.glb"), path)
            return
        with open(os.path.join(work, "t.ktx2"), "rb") as f:
            tam = f.read()
        kvd_off, kvd_len = struct.unpack_from("<II", tam, 56)
        data = I.ktx2_bytes(BOMB_SIDE, BOMB_SIDE, 8, 9, 1, bomb_levels(BOMB_SIDE, 8, 1, levels=15),
                            kvd=tam[kvd_off:kvd_off + kvd_len])
        I.write(path, replace_image(glb, data))
    return ctx.shared_file("tam-%s.glb" % ("bomb" if bomb else "control"), make, version="2")


def parse_glb(data):
    jlen = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + jlen])
    rest = data[20 + jlen:]
    blen = struct.unpack_from("<I", rest, 0)[0] if len(rest) >= 8 else 0
    return doc, rest[8:8 + blen]


def replace_image(glb, image_bytes):
    """The GLB with its first image's buffer view replaced by `image_bytes` (views laid out again)."""
    doc, bin_data = parse_glb(glb)
    target = doc["images"][0]["bufferView"]
    parts = []
    for k, view in enumerate(doc["bufferViews"]):
        chunk = image_bytes if k == target else bin_data[view.get("byteOffset", 0):view.get("byteOffset", 0) +
                                                         view["byteLength"]]
        parts.append(chunk)
    out = b""
    for k, chunk in enumerate(parts):
        out += b"\0" * ((-len(out)) % 16)
        doc["bufferViews"][k]["byteOffset"] = len(out)
        doc["bufferViews"][k]["byteLength"] = len(chunk)
        out += chunk
    doc["buffers"][0]["byteLength"] = len(out)
    return I.glb_bytes(json.dumps(doc, separators=(",", ":")), out)


def bomb_case(recipe, variant):
    def build(ctx):
        if variant == "zstd-cli" and not ZSTD:
            raise RuntimeError("zstd is not installed: the variant made by the zstd tool cannot be built")
        if recipe == "bakeplay-validate":
            src = tam_bomb_package(ctx, None if variant == "package-control" else True)
            path = place(ctx, src, ctx.path("pkg.glb"))
            inv = invoke(ctx, recipe, inp={"pkg": path})
        else:
            path = place(ctx, bomb_file(ctx, variant), ctx.path("tex.ktx2"))
            inv = invoke(ctx, recipe, inp={"file": path})
        control = variant in ("control", "package-control")
        return spec_of(inv, (0,) if control else (3,), [] if control else ["budget"], timeout=10)
    return Case("bomb", recipe, variant, build)


def class_bomb(env):
    cases = [bomb_case("bakeinfo", v) for v in ("rle-fcs", "rle-nofcs", "full-chain", "side", "zstd-cli", "control")]
    cases += [bomb_case("bakeplay-validate", v) for v in ("package-bomb", "package-control")]
    return cases


# ----------------------------------------------------------------------------------------------
# 7. budgets: huge-cost inputs

BUDGET_WORD = "--budget"


def budget_spec(inv, **kw):
    return spec_of(inv, (0, 3), checks=[stderr_when(3, BUDGET_WORD)], **kw)


def svg_segments(n):
    return "M0.5 0.5" + "h8e-6" * n


def budget_cases():
    cases = []

    def add(recipe, name, build):
        cases.append(Case("budgets", recipe, name, build))

    def groove_tiles(bond):
        def build(ctx):
            scene = I.groove_scene(svg_in_scene=False, generators=[{"tiles": {
                "tileSize": [1e-5, 1e-5], "count": [1000000, 1000000], "bond": bond, "profile": "v",
                "material": "m"}}])
            scene["profiles"]["v"]["points"] = [[-2e-6, 0], [0, -1e-6], [2e-6, 0]]
            path = I.write(ctx.path("tiles.json"), scene)
            return budget_spec(invoke(ctx, "groovebake", inp={"scene": path}))
        return build

    add("groovebake", "tiles-1e6x1e6-stack", groove_tiles("stack"))
    add("groovebake", "tiles-1e6x1e6-running", groove_tiles("running"))

    def groove_svg_inline(ctx):
        scene = I.groove_scene(svg_in_scene=False, extra_grooves=[
            {"name": "long", "profile": "v", "path": {"svg": svg_segments(1000000)}}])
        path = I.write(ctx.path("scene.json"), scene)
        return budget_spec(invoke(ctx, "groovebake", inp={"scene": path}))
    add("groovebake", "svg-path-1e6-segments", groove_svg_inline)

    def groove_svg_file(ctx):
        svg = I.write(ctx.path("long.svg"), '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><path d="'
                      + svg_segments(1000000) + '"/></svg>\n')
        return budget_spec(invoke(ctx, "groovebake", inp={"svg": svg}))
    add("groovebake", "svg-file-1e6-segments", groove_svg_file)

    def revol_svg(ctx):
        d = "M0 0L0.4 0" + "v-8e-7" * 1000000 + "L0 -0.8Z"
        svg = I.write(ctx.path("long.svg"), '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1 1"><path d="'
                      + d + '"/></svg>\n')
        return budget_spec(invoke(ctx, "revolbake", inp={"profile": svg}))
    add("revolbake", "svg-profile-1e6-segments", revol_svg)

    def strokes_points(points):
        def build(ctx):
            mesh = I.write(ctx.path("grow.obj"), I.obj_text(I.tetra()))
            doc = {"version": 1, "generators": [{"type": "grow", "mesh": "grow.obj", "count": 10000000,
                                                 "pointsPerStroke": points, "length": 0.01}]}
            path = I.write(ctx.path("strokes.json"), doc)
            spec = budget_spec(invoke(ctx, "strokebake", inp={"strokes": path}))
            spec.inputs.append(mesh)
            return spec
        return build
    add("strokebake", "control-points-at-limit-1e8", strokes_points(10))
    add("strokebake", "control-points-over-limit-1.1e8", strokes_points(11))

    def revol_png(side):
        def build(ctx):
            src = ctx.shared_file("profile-%d.png" % side, lambda p: I.write(p, I.png_profile(side, side)))
            path = place(ctx, src, ctx.path("profile.png"))
            return budget_spec(invoke(ctx, "revolbake", inp={"profile": path}))
        return build
    add("revolbake", "png-profile-16384", revol_png(16384))
    add("revolbake", "png-profile-16385", revol_png(16385))

    def big_gltf(recipe, slot):
        def build(ctx):
            mesh = mesh_for(recipe, slot)
            src = ctx.shared_file("data-uri-300MB-%s.gltf" % ("lathe" if recipe == "revolbake" else "tetra"),
                                  lambda p: I.write_big_data_uri_gltf(p, mesh, 300 * 1000 * 1002))
            path = place(ctx, src, ctx.path("big.gltf"))
            return budget_spec(invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra_for(recipe, slot, "gltf")))
        return build
    for recipe, slot in (("bakeinfo", "file"), ("geobake", "mesh"), ("bakeplay-validate", "pkg")):
        add(recipe, "gltf-data-uri-300MB", big_gltf(recipe, slot))

    def tam_max(ctx):
        style = {"tones": [round(0.05 + 0.055 * k, 3) for k in range(16)], "resolution": 4096, "levels": 12,
                 "candidates": 4096, "blurSigma": 64, "seed": 18446744073709551615,
                 "stroke": {"kind": "cross-hatching", "length": {"min": 1, "max": 1}, "width": {"min": 1, "max": 1},
                            "angle": 360, "angleJitter": 180, "curvature": 1, "crossFrom": 0, "crossAngle": 90,
                            "opacity": 1, "centreOpacity": 1, "edgeOpacity": 1, "taper": 0.5}}
        path = I.write(ctx.path("style.json"), style)
        return budget_spec(invoke(ctx, "tambake", inp={"style": path}, out={"--package": None}))
    add("tambake", "style-at-every-maximum", tam_max)

    def pipe_objects(recipe):
        def build(ctx):
            ring = I.write(ctx.path("ring.json"), I.RING_PROFILE)
            objects = [{"name": "o%d" % k, "technique": "revolution", "input": "ring.json", "material": "plain"}
                       for k in range(200000)]
            path = I.write(ctx.path("scene.json"), json.dumps(I.pipe_scene(objects=objects)))
            spec = budget_spec(invoke(ctx, recipe, inp={"scene": path, "input": ring}))
            return spec
        return build
    add("bakepipe-plan", "scene-200000-objects", pipe_objects("bakepipe-plan"))
    add("bakepipe-ninja", "scene-200000-objects", pipe_objects("bakepipe-ninja"))
    return cases


def class_budgets(env):
    return budget_cases()


# ----------------------------------------------------------------------------------------------
# 8. a UTF-8 byte order mark at the start of every text input

BOM = b"\xef\xbb\xbf"
BOM_INPUTS = [("geobake", "mesh", "obj"), ("geobake", "mesh", "ply"), ("geobake", "mesh", "off"),
              ("geobake", "mesh", "stl"), ("geobake", "sources", "json"),
              ("revolbake", "profile", "json"), ("revolbake", "profile", "csv"), ("revolbake", "profile", "svg"),
              ("revolbake", "profile", "obj"),
              ("groovebake", "scene", "json"), ("groovebake", "svg", "svg"), ("groovebake", "mesh", "obj"),
              ("tambake", "style", "json"), ("tambake", "mesh", "obj"),
              ("strokebake", "strokes", "json"), ("strokebake", "strokes", "csv"), ("strokebake", "strokes", "obj"),
              ("strokebake", "growmesh", "obj"),
              ("bakepipe-plan", "scene", "json"), ("bakepipe-ninja", "scene", "json")]


def bom_case(recipe, slot, ext):
    def build(ctx):
        path = slot_default_path(ctx, recipe, slot, ext, "text")
        body = valid_content(ctx, recipe, slot, ext)
        I.write(path, body)
        extra = extra_for(recipe, slot, ext)
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra)
        compared = {k: v for k, v in inv.outputs.items() if k != "--report"}
        plain = ctx.run_aux(inv.tool, inv.args)
        if plain.rc != 0:
            raise RuntimeError("the run without a BOM fails (exit %d): %s" % (plain.rc, plain.first_err()))
        saved = {}
        for opt, p in compared.items():
            with open(p, "rb") as f:
                saved[opt] = f.read()
        plain_stdout = plain.stdout
        I.write(path, BOM + body)

        def check(ctx, spec, res):
            problems = []
            if res.rc != 0:
                return problems
            for opt, p in compared.items():
                try:
                    with open(p, "rb") as f:
                        now = f.read()
                except OSError:
                    problems.append("%s %s not written" % (opt, os.path.basename(p)))
                    continue
                if now != saved[opt]:
                    problems.append("%s differs from the bake without the BOM" % opt)
            if recipe == "bakepipe-plan" and res.stdout != plain_stdout:
                problems.append("the plan differs from the one without the BOM")
            return problems
        return spec_of(inv, (0,), checks=[check])
    return Case("bom", recipe, "%s:%s" % (slot, ext), build)


def class_bom(env):
    return [bom_case(*k) for k in BOM_INPUTS]


# ----------------------------------------------------------------------------------------------
# 9. numeric options

HOSTILE_VALUES = ["4294967296", "18446744073709551616", "-1", "inf", "-inf", "nan", "1e300", "-1e300", "1e-320"]
NUMERIC_TYPES = re.compile(r"^(U?INT|FLOAT|NUMBER|DOUBLE|INT64|UINT64)\b")
TUPLES = [(re.compile(r"X,Y,Z\[:"), "{v},1,3"), (re.compile(r"eye x,y,z"), "{v},1,3"),
          (re.compile(r"(?i)\bx,y,z\b"), "{v},1,0"), (re.compile(r"R,G,B"), "{v},0.5,0.5"),
          (re.compile(r"\bU,V\b"), "{v},0"), (re.compile(r"WIDTHxHEIGHT|WxH"), "{v}x16"),
          (re.compile(r"SIDESxSTEPS"), "{v}x2")]

# The base run of each recipe for the numeric class: (args with {d}, options set in it).
NUMERIC_BASES = {
    "geobake": ["{d}/mesh.obj", "-o", "{d}/out.glb", "--source-vertex", "0", "--report", "{d}/report.json"],
    "bakeshape": ["sphere", "-o", "{d}/out.glb", "--resolution", "8", "--report", "{d}/report.json"],
    "revolbake": ["{d}/ring.json", "-o", "{d}/out.glb", "--resolution", "32", "--proxy-bands", "4",
                  "--report", "{d}/report.json"],
    "groovebake": ["{d}/scene.json", "-o", "{d}/out.glb", "--report", "{d}/report.json"],
    "tambake": ["{d}/style.json", "-o", "{d}/tam.ktx2", "--apply-to", "{d}/mesh.obj", "--package", "{d}/tpkg.glb",
                "--report", "{d}/report.json"],
    "strokebake": ["{d}/mesh.obj", "-o", "{d}/out.glb", "--count", "20", "--points", "3", "--report",
                   "{d}/report.json"],
    "bakeplay-render": ["render", "{d}/pkg.glb", "-o", "{d}/frame.png", "--size", "16x16", "--report",
                        "{d}/report.json"],
    "bakeplay-validate": ["validate", "{d}/pkg.glb", "--size", "16", "--report", "{d}/report.json"],
    "bakepipe-plan": ["plan", "{d}/scene.json", "--out-dir", "{d}/baked", "--json"],
    "bakepipe-ninja": ["ninja", "{d}/scene.json", "-o", "{d}/build.ninja", "--out-dir", "{d}/baked",
                       "--report", "{d}/report.json"],
    "bakeinfo": ["--json", "{d}/pkg.glb"],
}
NUMERIC_PACKAGES = {"geobake": "out.glb", "bakeshape": "out.glb", "revolbake": "out.glb", "groovebake": "out.glb",
                    "tambake": "tpkg.glb", "strokebake": "out.glb"}


def numeric_files(ctx, recipe):
    d = ctx.dir
    I.write(os.path.join(d, "mesh.obj"), I.obj_text(I.tetra()))
    I.write(os.path.join(d, "ring.json"), I.RING_PROFILE)
    I.write(os.path.join(d, "drawing.svg"), I.SVG_DRAWING)
    I.write(os.path.join(d, "style.json"), I.TAM_STYLE)
    if recipe.startswith("bakepipe"):
        I.write(os.path.join(d, "scene.json"), I.pipe_scene("ring.json"))
    else:
        I.write(os.path.join(d, "scene.json"), I.groove_scene("drawing.svg"))
    shutil.copyfile(tetra_glb(ctx), os.path.join(d, "pkg.glb"))
    return [os.path.join(d, n) for n in ("mesh.obj", "ring.json", "drawing.svg", "style.json", "scene.json",
                                         "pkg.glb")]


def parse_help(text):
    """Options of a CLI11 help text: [(names, type word, description)]."""
    found = []
    lines = text.splitlines()
    for k, line in enumerate(lines):
        m = re.match(r"^\s{2,}((?:-\w,)?--[\w-]+(?:\{\w*\})?)(?:\s(\S+))?(.*)$", line)
        if not m:
            continue
        names = m.group(1).split("{")[0]
        word = m.group(2) or ""
        desc = m.group(3).strip()
        if not desc and k + 1 < len(lines) and not re.match(r"^\s{2,}-", lines[k + 1]):
            desc = lines[k + 1].strip()
        found.append((names, word, desc))
    return found


def numeric_options(env, recipe):
    tool = R.TOOL_OF[recipe]
    sub = recipe.split("-", 1)[1] if "-" in recipe else None
    text = env.help_text(tool, sub)
    opts = []
    for names, word, desc in parse_help(text):
        long = [n for n in names.split(",") if n.startswith("--")][0]
        if long in ("--help", "--version"):
            continue
        if long == "--budget":
            opts.append((long, "input-bytes={v}", "int"))
        elif NUMERIC_TYPES.match(word):
            opts.append((long, "{v}", "int" if "INT" in word.split(":")[0] else "float"))
        elif word.startswith("TEXT"):
            for pattern, template in TUPLES:
                if pattern.search(desc):
                    opts.append((long, template, "int" if "x" in template else "float"))
                    break
    return opts


def json_number_paths(value, path="", out=None):
    out = set() if out is None else out
    if isinstance(value, dict):
        for k, v in value.items():
            json_number_paths(v, path + "/" + k, out)
    elif isinstance(value, list):
        for v in value:
            json_number_paths(v, path + "/*", out)
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        out.add(path)
    return out


def json_problems(text, baseline_numbers, what):
    problems = []
    for token in ("NaN", "Infinity"):
        if re.search(r"[:\[,]\s*-?%s\b" % token, text):
            problems.append("%s holds %s" % (what, token))
    try:
        doc = json.loads(text)
    except ValueError as e:
        return problems + ["%s is not JSON: %s" % (what, e)]

    def walk(value, path):
        if isinstance(value, dict):
            for k, v in value.items():
                walk(v, path + "/" + k)
        elif isinstance(value, list):
            for v in value:
                walk(v, path + "/*")
        elif value is None and path in baseline_numbers:
            problems.append("%s: %s is null where a number is expected" % (what, path))
        elif isinstance(value, float) and (value != value or value in (float("inf"), float("-inf"))):
            problems.append("%s: %s is not finite" % (what, path))
    walk(doc, "")
    return problems


def glb_json_text(path):
    with open(path, "rb") as f:
        data = f.read()
    jlen = struct.unpack_from("<I", data, 12)[0]
    return data[20:20 + jlen].decode("utf-8", "replace")


def numeric_json_outputs(recipe, d, res):
    outs = {}
    report = os.path.join(d, "report.json")
    if os.path.exists(report):
        with open(report, encoding="utf-8", errors="replace") as f:
            outs["report"] = f.read()
    pkg = NUMERIC_PACKAGES.get(recipe)
    if pkg and os.path.exists(os.path.join(d, pkg)):
        try:
            outs["package JSON"] = glb_json_text(os.path.join(d, pkg))
        except (OSError, struct.error):
            pass
    if recipe in ("bakeinfo", "bakepipe-plan"):
        outs["stdout"] = res.out
    return outs


def numeric_baseline(ctx, recipe):
    """Number paths of the JSON outputs of the base run (for 'null where a number is expected')."""
    def fn():
        d = os.path.join(ctx.env.tmp, "numeric", "_baseline", recipe)
        if os.path.exists(d):
            shutil.rmtree(d)
        os.makedirs(d)
        numeric_files(Ctx(ctx.env, ctx.case, d), recipe)
        args = [a.replace("{d}", d) for a in NUMERIC_BASES[recipe]]
        res = ctx.env.run_tool(R.TOOL_OF[recipe], args, d, tag="baseline")
        if res.rc != 0:
            raise RuntimeError("the base run fails (exit %d): %s" % (res.rc, res.first_err()))
        paths = {}
        for what, text in numeric_json_outputs(recipe, d, res).items():
            try:
                paths[what] = json_number_paths(json.loads(text))
            except ValueError:
                paths[what] = set()
        return paths
    return ctx.shared("numeric-baseline:" + recipe, fn)


def numeric_case(recipe, opt, template, value):
    def build(ctx):
        d = ctx.dir
        files = numeric_files(ctx, recipe)
        base = [a.replace("{d}", d) for a in NUMERIC_BASES[recipe]]
        if opt in base:  # the option under test replaces the base run's value
            k = base.index(opt)
            del base[k:k + 2]
        text = template.format(v=value)
        args = base + ["%s=%s" % (opt, text)]
        baseline = numeric_baseline(ctx, recipe)
        outputs = [p for p in (os.path.join(d, n) for n in ("out.glb", "tam.ktx2", "tpkg.glb", "frame.png",
                                                           "build.ninja", "report.json")) if p in args]

        def check(ctx, spec, res):
            if res.rc != 0:
                return []
            problems = []
            for what, text_ in numeric_json_outputs(recipe, d, res).items():
                problems += json_problems(text_, baseline.get(what, set()), what)
            return problems

        pkg = NUMERIC_PACKAGES.get(recipe)
        report = os.path.join(d, "report.json")
        spec = Spec(tool=R.TOOL_OF[recipe], args=args, expect=(0, 1), frags=[opt], inputs=files,
                    outputs=[p for p in outputs if p not in files], checks=[check],
                    reports=[report] if report in args else [], frags_stdout=recipe == "bakeplay-validate",
                    validate=[os.path.join(d, pkg)] if pkg else [])
        return spec
    return Case("numeric", recipe, "%s=%s" % (opt.lstrip("-"), value), build)


INT_ORDER = ["4294967296", "18446744073709551616", "-1", "1e300", "nan", "inf", "-1e300", "1e-320", "-inf"]
FLOAT_ORDER = ["nan", "inf", "1e300", "-1e300", "1e-320", "-inf", "-1", "4294967296", "18446744073709551616"]
# Options that every tool shares (parsed by one piece of code): in the default selection, only here.
SHARED_OPTIONS = {"--budget": ("geobake", "bakeplay-render"), "--threads": ("revolbake", "strokebake")}


def class_numeric(env):
    """Default: each numeric option of each tool gets a share of the hostile values (at least one), in
    an order that suits its type, so that each tool meets every value; the shared options (--budget,
    --threads) are tried on two tools. --full: every value on every option of every tool."""
    cases = []
    for recipe in NUMERIC_BASES:
        opts = numeric_options(env, recipe)
        if not env.full:
            opts = [o for o in opts if o[0] not in SHARED_OPTIONS or recipe in SHARED_OPTIONS[o[0]]]
        share = -(-len(HOSTILE_VALUES) // max(1, len(opts)))
        start = 0
        for opt, template, kind in opts:
            order = INT_ORDER if kind == "int" else FLOAT_ORDER
            if env.full:
                values = HOSTILE_VALUES
            else:
                values = [order[(start + j) % len(order)] for j in range(min(share, len(order)))]
                start += share
            for value in values:
                cases.append(numeric_case(recipe, opt, template, value))
    return cases


# ----------------------------------------------------------------------------------------------
# 10. depfiles with odd characters

DEP_CHARS = [("colon", ":"), ("space", " "), ("hash", "#"), ("dollar", "$"), ("newline", "\n")]
DEP_RECIPES = ["geobake", "bakeshape", "revolbake", "groovebake", "tambake", "strokebake", "bakeplay-render",
               "bakepipe-ninja", "bakepipe-assemble"]
MAIN_SLOT = {"geobake": ("mesh", "obj"), "revolbake": ("profile", "json"), "groovebake": ("scene", "json"),
             "tambake": ("style", "json"), "strokebake": ("strokes", "json"), "bakeplay-render": ("pkg", "glb"),
             "bakepipe-ninja": ("scene", "json"), "bakepipe-assemble": ("scene", "json")}


def make_escape(path):
    return path.replace("$", "$$").replace(" ", "\\ ").replace("#", "\\#").replace(":", "\\:")


def depfile_case(recipe, position, label, ch):
    def build(ctx):
        d = ctx.dir
        inp = {}
        main_input = None
        if position == "input":
            slot, ext = MAIN_SLOT[recipe]
            main_input = ctx.path("in%sputfile.%s" % (ch, ext))
            I.write(main_input, valid_content(ctx, recipe, slot, ext))
            inp[slot] = main_input
        out_ext_ = R.MAIN_OUT_EXT[recipe]
        output = ctx.path("out%sputfile%s" % (ch, out_ext_)) if position == "output" else ctx.path("out" + out_ext_)
        dep = ctx.path("dep.d")
        inv = invoke(ctx, recipe, inp=inp, out={"-o": output, "--depfile": dep})
        if recipe in MAIN_SLOT:  # the input touched below, odd name or not
            main_input = inv.inputs[MAIN_SLOT[recipe][0]]
        if "\n" in ch:
            spec = spec_of(inv, (1,), ["putfile"], sentinel=False)
            # The failure report is written (formats/report.md); every other output must not be.
            spec.absent = [p for k, p in inv.outputs.items() if k != "--report"]
            return spec

        def check(ctx, spec, res):
            if res.rc != 0:
                return []
            if not os.path.isfile(dep):
                return ["no depfile written"]
            mk = ctx.path("hostile.mk")
            with open(mk, "w") as f:
                f.write("all: %s\n%s:\n\t@echo HOSTILE-REMAKE\ninclude dep.d\n" % (make_escape(output),
                                                                                  make_escape(output)))
            problems = []
            r = subprocess.run([MAKE, "-n", "-f", mk], cwd=d, capture_output=True, timeout=30)
            text = (r.stdout + r.stderr).decode("utf-8", "replace")
            if r.returncode != 0:
                return ["make cannot read the depfile (exit %d): %s" % (r.returncode,
                                                                         text.strip().splitlines()[-1:])]
            if "HOSTILE-REMAKE" in text:
                problems.append("make thinks the fresh output is out of date (the depfile names another target)")
            if main_input:
                t = time.time() + 1000
                os.utime(main_input, (t, t))
                r = subprocess.run([MAKE, "-n", "-f", mk], cwd=d, capture_output=True, timeout=30)
                text = (r.stdout + r.stderr).decode("utf-8", "replace")
                if r.returncode != 0:
                    problems.append("make fails after touching the input (exit %d)" % r.returncode)
                elif "HOSTILE-REMAKE" not in text:
                    problems.append("touching the input does not make the output out of date")
            return problems
        return spec_of(inv, (0,), checks=[check])
    return Case("depfile", recipe, "%s-%s" % (position, label), build)


def class_depfile(env):
    """Default: each tool meets every character once, in its input's name or in its output's
    (alternating), the newline in one of them. --full: every character in both."""
    cases = []
    for k, recipe in enumerate(DEP_RECIPES):
        positions = ("input", "output") if recipe in MAIN_SLOT else ("output",)
        for j, (label, ch) in enumerate(DEP_CHARS):
            chosen = positions if env.full else (positions[(k + j) % len(positions)],)
            for position in chosen:
                cases.append(depfile_case(recipe, position, label, ch))
    return cases


# ----------------------------------------------------------------------------------------------
# 11. glTF buffer URIs outside the file's folder

URI_READERS = [("bakeinfo", "file"), ("geobake", "mesh"), ("revolbake", "profile"), ("tambake", "mesh"),
               ("strokebake", "strokes"), ("bakeplay-validate", "pkg"), ("bakeplay-render", "pkg")]
URI_VARIANTS = [("parent", "../x.bin", True), ("absolute", "{abs}", True), ("sub-parent-parent", "sub/../../x.bin", True),
                ("percent-dots", "%2e%2e/x.bin", True), ("percent-dots-slash", "%2E%2E%2Fx.bin", True),
                ("inside", "x.bin", False), ("sub-parent-inside", "sub/../x.bin", False)]


def uri_case(recipe, slot, label, uri, outside, allow):
    def build(ctx):
        mesh = mesh_for(recipe, slot)
        pkg_dir = ctx.path("pkg")
        os.makedirs(os.path.join(pkg_dir, "sub"))
        doc, data = I.gltf_doc(mesh)
        bin_path = ctx.path("x.bin") if outside else os.path.join(pkg_dir, "x.bin")
        I.write(bin_path, data)
        doc["buffers"][0]["uri"] = uri.replace("{abs}", ctx.path("x.bin"))
        path = I.write(os.path.join(pkg_dir, "model.gltf"), doc)
        extra = extra_for(recipe, slot, "gltf") + (["--allow-outside-uris"] if allow else [])
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra)
        spec = spec_of(inv, (3,) if outside and not allow else (0,), ["outside"])
        spec.inputs.append(bin_path)
        return spec
    return Case("uris", recipe, "%s%s" % (label, "+allow" if allow else ""), build)


def class_uris(env):
    """Default: each reader gets three of the outside spellings (rotating), one with
    --allow-outside-uris, and one inside control (alternating). --full: every spelling, with and
    without the option, and both controls."""
    cases = []
    outside = [v for v in URI_VARIANTS if v[2]]
    inside = [v for v in URI_VARIANTS if not v[2]]
    for k, (recipe, slot) in enumerate(URI_READERS):
        if env.full:
            for label, uri, out in URI_VARIANTS:
                cases.append(uri_case(recipe, slot, label, uri, out, False))
                if out:
                    cases.append(uri_case(recipe, slot, label, uri, out, True))
            continue
        for j in range(3):
            label, uri, out = outside[(k * 3 + j) % len(outside)]
            cases.append(uri_case(recipe, slot, label, uri, out, False))
        label, uri, out = outside[(k * 3 + 3) % len(outside)]
        cases.append(uri_case(recipe, slot, label, uri, out, True))
        label, uri, out = inside[k % len(inside)]
        cases.append(uri_case(recipe, slot, label, uri, out, False))
    return cases


# ----------------------------------------------------------------------------------------------
# 12. exit codes

PROC_MEM_INPUTS = [("geobake", "mesh", "obj"), ("geobake", "sources", "json"), ("revolbake", "profile", "json"),
                   ("revolbake", "height", "png"), ("groovebake", "scene", "json"), ("groovebake", "svg", "svg"),
                   ("tambake", "style", "json"), ("tambake", "mesh", "obj"), ("strokebake", "strokes", "json"),
                   ("strokebake", "strokes", "csv"), ("bakeplay-validate", "pkg", "glb"),
                   ("bakeplay-render", "pkg", "glb"), ("bakepipe-plan", "scene", "json"),
                   ("bakepipe-assemble", "pkg", "glb"), ("bakeinfo", "file", "glb"), ("bakeinfo", "file", "ktx2")]


def proc_mem_case(recipe, slot, ext, literal=False):
    def build(ctx):
        if literal:
            path = "/proc/self/mem"
        else:
            path = slot_default_path(ctx, recipe, slot, ext, "mem")
            os.symlink("/proc/self/mem", path)
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra_for(recipe, slot, ext))
        spec = spec_of(inv, (2,), [os.path.basename(path)])
        spec.inputs = [p for p in spec.inputs if p != path and not p.startswith("/proc")]
        return spec
    return Case("exitcodes", recipe, "proc-self-mem-%s:%s%s" % (slot, ext, "-literal" if literal else ""), build)


def long_name_case(recipe, opt):
    def build(ctx):
        ext = out_ext(recipe, opt)
        name = "n" * (250 - len(ext)) + ext
        inv = invoke(ctx, recipe, out={opt: ctx.path(name)})
        return spec_of(inv, (0,), checks=[lambda c, s, r: [] if r.rc != 0 or os.path.isfile(c.path(name))
                                          else ["the 250-byte output was not written"]])
    return Case("exitcodes", recipe, "output-name-250-bytes-%s" % opt.lstrip("-"), build)


GLB_READERS = [("bakeinfo", "file"), ("geobake", "mesh"), ("revolbake", "profile"), ("tambake", "mesh"),
               ("strokebake", "strokes"), ("bakeplay-validate", "pkg")]


def glb_past_end_case(recipe, slot, variant):
    def build(ctx):
        mesh = mesh_for(recipe, slot)
        doc, data = I.gltf_doc(mesh)
        text = json.dumps(doc, separators=(",", ":"))
        if variant == "json-chunk":
            blob = I.glb_bytes(text, data, json_len=len(text) + 4096)
        elif variant == "bin-chunk":
            blob = I.glb_bytes(text, data, bin_len=len(data) + 4096)
        else:  # the header's total length past the end, and the BIN chunk cut short
            full = I.glb_bytes(text, data)
            blob = full[:-8]
        path = I.write(ctx.path("cut.glb"), blob)
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,), extra=extra_for(recipe, slot, "glb"))
        return spec_of(inv, (3,), ["cut.glb"])
    return Case("exitcodes", recipe, "glb-%s-past-end" % variant, build)


def sources_case(variant):
    def build(ctx):
        doc = json.loads(json.dumps(I.SOURCES))
        if variant == "unknown-top-key":
            doc["colour"] = [1, 0, 0]
        elif variant == "unknown-field-key":
            doc["fields"][0]["weight"] = 2
        elif variant == "unknown-source-key":
            doc["fields"][0]["sources"][0]["radius"] = 1
        elif variant == "vertex-and-point":
            doc["fields"][0]["sources"][0]["point"] = [0, 0, 0]
        elif variant == "65-fields":
            doc["fields"] = [{"name": "f%d" % k, "sources": [{"vertex": k % 4}]} for k in range(65)]
        path = I.write(ctx.path("sources.json"), doc)
        inv = invoke(ctx, "geobake", inp={"sources": path})
        return spec_of(inv, (3,), ["sources.json"])
    return Case("exitcodes", "geobake", "sources-%s" % variant, build)


def class_exitcodes(env):
    """Default: /proc/self/mem as the first input kind of each tool; a 250-byte name for -o of every
    writer and for each other output option on one tool; a GLB cut short in its three ways for
    bakeinfo and in one way (rotating) for each other reader. --full: all of them everywhere."""
    cases = []
    seen = set()
    for recipe, slot, ext in PROC_MEM_INPUTS:
        if env.full or recipe not in seen:
            cases.append(proc_mem_case(recipe, slot, ext))
        seen.add(recipe)
    cases.append(proc_mem_case("bakeinfo", "file", "", literal=True))
    other_done = set()
    for recipe in R.WRITERS:
        for opt in R.OUTPUTS[recipe]:
            if env.full or opt == "-o" or opt not in other_done:
                cases.append(long_name_case(recipe, opt))
                other_done.add(opt)
    variants = ("json-chunk", "bin-chunk", "total-length")
    for k, (recipe, slot) in enumerate(GLB_READERS):
        for variant in variants if (env.full or recipe == "bakeinfo") else (variants[k % 3],):
            cases.append(glb_past_end_case(recipe, slot, variant))
    for variant in ("unknown-top-key", "unknown-field-key", "unknown-source-key", "vertex-and-point", "65-fields"):
        cases.append(sources_case(variant))
    return cases


# ----------------------------------------------------------------------------------------------
# 13. messages

TINY = re.compile(r"-?1(\.0*)?e-300")
HUGE = re.compile(r"1(\.0*)?e\+?300")


def empty_output_case(recipe, opt):
    def build(ctx):
        inv = invoke(ctx, recipe, out={opt: ""})
        names = [opt] + (["--output"] if opt == "-o" else [])
        return spec_of(inv, (1,), [tuple(names)])
    return Case("messages", recipe, "empty-%s" % opt.lstrip("-"), build)


def number_case(recipe, slot, ext, label, mutate, pattern):
    def build(ctx):
        if ext == "csv":
            text = mutate(None)
        else:
            doc = json.loads(valid_content(ctx, recipe, slot, ext))
            mutate(doc)
            text = json.dumps(doc)
        path = I.write(ctx.path("input." + ext), text)
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,))
        return spec_of(inv, (3,), [pattern])
    return Case("messages", recipe, "number-%s" % label, build)


def _set(path, value):
    def mutate(doc):
        at = doc
        for k in path[:-1]:
            at = at[k]
        at[path[-1]] = value
    return mutate


NUMBER_CASES = [
    ("strokebake", "strokes", "json", "stroke-radius--1e-300", _set(["strokes", 0, "points", 0, "r"], -1e-300), TINY),
    ("strokebake", "strokes", "json", "stroke-coordinate-1e300", _set(["strokes", 0, "points", 0, "p", 0], 1e300), HUGE),
    ("strokebake", "strokes", "csv", "csv-radius--1e-300",
     lambda _: I.STROKES_CSV.replace("1,0,0,0,0.02", "1,0,0,0,-1e-300", 1), TINY),
    ("tambake", "style", "json", "style-width--1e-300", _set(["stroke", "width", "min"], -1e-300), TINY),
    ("tambake", "style", "json", "style-blur--1e-300", _set(["blurSigma"], -1e-300), TINY),
    ("tambake", "style", "json", "style-blur-1e300", _set(["blurSigma"], 1e300), HUGE),
    ("groovebake", "scene", "json", "domain--1e-300", _set(["domain", "size", 0], -1e-300), TINY),
    ("groovebake", "scene", "json", "shininess--1e-300", _set(["materials", "m", "shininess"], -1e-300), TINY),
    # A profile 1e-296 tall, so that r = -1e-300 lies beyond any tolerance relative to its size.
    ("revolbake", "profile", "json", "profile-r--1e-300",
     _set(["contours"], [{"closed": True, "points": [[-1e-300, 0], [1e-296, 0], [1e-296, 1e-296], [0, 1e-296]]}]),
     TINY),
    ("revolbake", "profile", "csv", "csv-r--1e-300",
     lambda _: "# r,h,bulge\n-1e-300,0,0\n1e-296,0,0\n1e-296,1e-296,0\n0,1e-296,0\n", TINY),
    ("bakepipe-plan", "scene", "json", "scene-scale--1e-300", _set(["objects", 0, "scale"], -1e-300), TINY),
]


def nul_key_case(recipe, slot, where):
    def build(ctx):
        doc = json.loads(valid_content(ctx, recipe, slot, "json"))
        target = doc
        for k in where:
            target = target[k]
        target["bad\u0000keytail"] = 1
        path = I.write(ctx.path("input.json"), json.dumps(doc))
        inv = invoke(ctx, recipe, inp={slot: path}, use=(slot,))

        def check(ctx, spec, res):
            if res.rc != 3:
                return []
            problems = []
            lines = [l for l in res.stderr.split(b"\n") if b": error:" in l]
            if not lines:
                return ["no error line"]
            line = lines[0]
            if b"keytail" not in line:
                problems.append("the message stops at the NUL (no 'keytail' after it): %r" % line[:120])
            if b"input.json" not in line:
                problems.append("the message does not name the file")
            if not res.stderr.endswith(b"\n"):
                problems.append("stderr does not end with a newline")
            return problems
        return spec_of(inv, (3,), checks=[check])
    return Case("messages", recipe, "nul-in-key%s" % ("-" + "-".join(map(str, where)) if where else ""), build)


NUL_KEYS = [("geobake", "sources", []), ("geobake", "sources", ["fields", 0]), ("revolbake", "profile", []),
            ("groovebake", "scene", []), ("tambake", "style", []), ("strokebake", "strokes", []),
            ("bakepipe-plan", "scene", [])]


def class_messages(env):
    cases = []
    other_done = set()
    for recipe in R.WRITERS:
        for opt in R.OUTPUTS[recipe]:
            if env.full or opt == "-o" or opt not in other_done:
                cases.append(empty_output_case(recipe, opt))
                other_done.add(opt)
    for k in NUMBER_CASES:
        cases.append(number_case(*k))
    for k in NUL_KEYS:
        cases.append(nul_key_case(*k))
    return cases


# ----------------------------------------------------------------------------------------------
# 14. late failures: an unwritable output with a large input

def big_mesh(ctx, ext):
    mesh = lambda: I.lathe(500, rings=201)  # 201,000 triangles
    if ext == "obj":
        return ctx.shared_file("big200k.obj", lambda p: I.write(p, I.obj_text(mesh())))
    return ctx.shared_file("big200k.glb", lambda p: I.write(p, I.glb_of(mesh())))


def late_invocation(ctx, recipe, out):
    d = ctx.dir
    if recipe in ("geobake", "tambake", "strokebake", "revolbake"):
        big = place(ctx, big_mesh(ctx, "obj"), ctx.path("big.obj"))
        slot = {"geobake": "mesh", "tambake": "mesh", "strokebake": "strokes", "revolbake": "profile"}[recipe]
        extra = {"geobake": ["--source-vertex", "0", "--method", "fmm"],
                 "strokebake": ["--count", "100000", "--points", "4"]}.get(recipe, [])
        return invoke(ctx, recipe, inp={slot: big}, out=out, extra=extra)
    if recipe == "bakeplay-render":
        big = place(ctx, big_mesh(ctx, "glb"), ctx.path("big.glb"))
        return invoke(ctx, recipe, inp={"pkg": big}, out=out)
    if recipe == "groovebake":
        scene = I.groove_scene(svg_in_scene=False, generators=[{"tiles": {
            "tileSize": [0.05, 0.05], "count": [200, 200], "bond": "running", "profile": "v", "material": "m"}}])
        scene["profiles"]["v"]["points"] = [[-0.005, 0], [0, -0.002], [0.005, 0]]
        path = I.write(ctx.path("tiles.json"), scene)
        return invoke(ctx, recipe, inp={"scene": path}, out=out)
    if recipe == "bakeshape":
        return invoke(ctx, recipe, out=out, extra=["--resolution", "160"])
    if recipe == "bakepipe-ninja":
        ring = I.write(ctx.path("ring.json"), I.RING_PROFILE)
        objects = [{"name": "o%d" % k, "technique": "revolution", "input": "ring.json", "material": "plain"}
                   for k in range(20000)]
        scene = I.write(ctx.path("scene.json"), json.dumps(I.pipe_scene(objects=objects)))
        return invoke(ctx, recipe, inp={"scene": scene, "input": ring}, out=out)
    raise ValueError(recipe)


LATE_RECIPES = ["geobake", "bakeshape", "revolbake", "groovebake", "tambake", "strokebake", "bakeplay-render",
                "bakepipe-ninja"]


def late_case(recipe, opt, kind):
    def build(ctx):
        name = os.path.basename(R.default_output(ctx.dir, recipe, opt))
        if kind == "missing-folder":
            target = ctx.path("no-such-folder", name)
        else:
            I.write(ctx.path("plainfile"), "a regular file, not a folder\n")
            target = ctx.path("plainfile", name)
        inv = late_invocation(ctx, recipe, {opt: target})
        spec = spec_of(inv, (2,), [target])

        def note(ctx, spec, res):
            ctx.notes.append("the run took %.1f s" % res.elapsed)
            return []
        spec.checks.append(note)
        spec.absent = [target]
        return spec
    return Case("late", recipe, "%s=%s" % (opt.lstrip("-"), kind), build)


def class_late(env):
    cases = []
    other_done = set()
    for recipe in LATE_RECIPES:
        for k, opt in enumerate(R.OUTPUTS[recipe]):
            if env.full:
                kinds = ("missing-folder", "folder-is-a-file")
            elif opt == "-o":
                kinds = ("missing-folder", "folder-is-a-file")
            elif opt not in other_done:
                kinds = (("missing-folder",) if k % 2 else ("folder-is-a-file",))
            else:
                kinds = ()
            for kind in kinds:
                other_done.add(opt)
                cases.append(late_case(recipe, opt, kind))
    return cases


# ----------------------------------------------------------------------------------------------

CLASSES = {
    "ninja": class_ninja,
    "aliasing": class_aliasing,
    "nonregular-out": class_nonregular_out,
    "recursion": class_recursion,
    "nonregular-in": class_nonregular_in,
    "bomb": class_bomb,
    "budgets": class_budgets,
    "bom": class_bom,
    "numeric": class_numeric,
    "depfile": class_depfile,
    "uris": class_uris,
    "exitcodes": class_exitcodes,
    "messages": class_messages,
    "late": class_late,
}
