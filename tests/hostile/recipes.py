"""Recipes: one small, fast, valid invocation of each tool (or subcommand), with its input slots and
output options named, so that a class can replace any one input or output by something hostile.

A recipe is called as recipe(ctx, inp=None, out=None, use=(), extra=()) and returns an Inv. `inp`
maps a slot to a path that the case has already prepared (it is used as is); other slots get a fresh
valid file in the case folder. `out` maps an output option to a path (None: leave the option out).
`use` turns on optional slots. Paths are absolute unless the case passes something else."""

import json
import os
import shutil
from dataclasses import dataclass, field

import inputs as I


@dataclass
class Inv:
    recipe: str
    tool: str
    args: list
    inputs: dict            # slot -> path (as passed or as referenced)
    outputs: dict           # option -> path
    packages: list = field(default_factory=list)  # outputs that are glTF packages (for validation)
    cwd: str = None


@dataclass
class Slot:
    ext: str
    how: str          # 'arg' (on the command line) or 'ref' (named inside another input)
    optional: bool = False
    text: bool = False  # a text format (BOM class)


# Slot tables: recipe -> slot -> Slot. Output tables: recipe -> [options].
SLOTS = {
    "geobake": {"mesh": Slot("obj", "arg", text=True), "sources": Slot("json", "arg", text=True)},
    "bakeshape": {},
    "revolbake": {"profile": Slot("json", "arg", text=True), "height": Slot("png", "arg"),
                  "colour": Slot("png", "arg")},
    "groovebake": {"scene": Slot("json", "arg", text=True), "svg": Slot("svg", "ref", text=True),
                   "mesh": Slot("obj", "arg", optional=True, text=True)},
    "tambake": {"style": Slot("json", "arg", text=True), "mesh": Slot("obj", "arg", text=True),
                "image": Slot("png", "ref", optional=True)},
    "strokebake": {"strokes": Slot("json", "arg", text=True), "growmesh": Slot("obj", "ref", optional=True, text=True)},
    "bakeplay-render": {"pkg": Slot("glb", "arg")},
    "bakeplay-validate": {"pkg": Slot("glb", "arg")},
    "bakepipe-plan": {"scene": Slot("json", "arg", text=True), "input": Slot("json", "ref", text=True)},
    "bakepipe-ninja": {"scene": Slot("json", "arg", text=True), "input": Slot("json", "ref", text=True)},
    "bakepipe-assemble": {"scene": Slot("json", "arg", text=True), "pkg": Slot("glb", "ref")},
    "bakeinfo": {"file": Slot("glb", "arg")},
}

OUTPUTS = {
    "geobake": ["-o", "--report", "--depfile"],
    "bakeshape": ["-o", "--report", "--depfile"],
    "revolbake": ["-o", "--report", "--depfile"],
    "groovebake": ["-o", "--report", "--depfile"],
    "tambake": ["-o", "--threshold", "--package", "--report", "--depfile"],
    "strokebake": ["-o", "--report", "--depfile"],
    "bakeplay-render": ["-o", "--report", "--depfile"],
    "bakeplay-validate": ["--report"],
    "bakepipe-plan": [],
    "bakepipe-ninja": ["-o", "--report", "--depfile"],
    "bakepipe-assemble": ["-o", "--report", "--depfile"],
    "bakeinfo": [],
}

OUT_NAMES = {"-o": "out", "--report": "report.json", "--depfile": "out.d", "--threshold": "threshold.ktx2",
             "--package": "package.glb"}
MAIN_OUT_EXT = {"geobake": ".glb", "bakeshape": ".glb", "revolbake": ".glb", "groovebake": ".glb",
                "tambake": ".ktx2", "strokebake": ".glb", "bakeplay-render": ".png", "bakepipe-ninja": ".ninja",
                "bakepipe-assemble": ".glb"}

TOOL_OF = {r: r.split("-")[0] for r in SLOTS}
BAKERS = ["geobake", "bakeshape", "revolbake", "groovebake", "tambake", "strokebake"]
# Recipes that write files (every output option): the bakers, bakeplay render/validate, bakepipe.
WRITERS = [r for r in OUTPUTS if OUTPUTS[r]]


def default_output(d, recipe, opt):
    if opt == "-o":
        return os.path.join(d, "out" + MAIN_OUT_EXT[recipe])
    return os.path.join(d, OUT_NAMES[opt])


def _outs(d, recipe, out):
    """The output options of a run: defaults, overridden or dropped (None) by `out`."""
    out = out or {}
    result = {}
    for opt in OUTPUTS[recipe]:
        if opt in out:
            if out[opt] is not None:
                result[opt] = out[opt]
        else:
            result[opt] = default_output(d, recipe, opt)
    return result


def _outargs(outs, skip=()):
    args = []
    for opt, path in outs.items():
        if opt in skip:
            continue
        args += [opt, path]
    return args


def _ref(d, path):
    """How a file is named inside another input of the folder `d`: relative when it lies in `d`."""
    if path.startswith(d.rstrip("/") + "/"):
        return path[len(d.rstrip("/")) + 1:]
    return path


def _file(d, inp, slot, name, content):
    """The slot's path: the case's override, or a fresh valid file `name` in the folder."""
    if slot in inp:
        return inp[slot]
    return I.write(os.path.join(d, name), content)


def geobake(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    mesh = _file(d, inp, "mesh", "mesh.obj", I.obj_text(I.tetra()))
    sources = _file(d, inp, "sources", "sources.json", I.SOURCES)
    outs = _outs(d, "geobake", out)
    args = [mesh] + _outargs(outs) + ["--sources", sources, "-j", "1"] + list(extra)
    return Inv("geobake", "geobake", args, {"mesh": mesh, "sources": sources}, outs,
               packages=[outs["-o"]] if "-o" in outs else [])


def bakeshape(ctx, inp=None, out=None, use=(), extra=()):
    outs = _outs(ctx.dir, "bakeshape", out)
    args = ["sphere"] + _outargs(outs) + ([] if "--resolution" in extra else ["--resolution", "8"]) + list(extra)
    return Inv("bakeshape", "bakeshape", args, {}, outs, packages=[outs["-o"]] if "-o" in outs else [])


def revolbake(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    profile = _file(d, inp, "profile", "profile.json", I.RING_PROFILE)
    height = _file(d, inp, "height", "height.png", I.png_pattern(16, 16))
    colour = _file(d, inp, "colour", "colour.png", I.png_pattern(8, 8, 2))
    outs = _outs(d, "revolbake", out)
    args = [profile] + _outargs(outs) + ["--resolution", "32", "--height-map", height, "--base-color", colour,
                                         "--proxy-bands", "4", "-j", "1"] + list(extra)
    return Inv("revolbake", "revolbake", args, {"profile": profile, "height": height, "colour": colour}, outs,
               packages=[outs["-o"]] if "-o" in outs else [])


def groovebake(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    svg = _file(d, inp, "svg", "drawing.svg", I.SVG_DRAWING)
    ref = _ref(d, svg)
    scene = _file(d, inp, "scene", "scene.json", I.groove_scene(ref))
    ins = {"scene": scene, "svg": svg}
    outs = _outs(d, "groovebake", out)
    args = [scene] + _outargs(outs) + ["-j", "1"] + list(extra)
    if "mesh" in inp or "mesh" in use:  # the grooves drawn on a UV-mapped mesh
        ins["mesh"] = _file(d, inp, "mesh", "mesh.obj", I.obj_text_uv(I.tetra()))
        args += ["--apply-to", ins["mesh"]]
    return Inv("groovebake", "groovebake", args, ins, outs, packages=[outs["-o"]] if "-o" in outs else [])


def tambake(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    ins = {}
    if "image" in inp or "image" in use:
        image = _file(d, inp, "image", "stroke.png", I.png_pattern(16, 4))
        style_doc = json.loads(json.dumps(I.TAM_STYLE))
        style_doc["stroke"] = {"kind": "image", "image": _ref(d, image), "length": {"min": 0.3, "max": 0.5},
                               "width": {"min": 1.0, "max": 1.5}}
        ins["image"] = image
    else:
        style_doc = I.TAM_STYLE
    style = _file(d, inp, "style", "style.json", style_doc)
    mesh = _file(d, inp, "mesh", "mesh.obj", I.obj_text(I.tetra()))
    outs = _outs(d, "tambake", out)
    args = [style] + _outargs(outs, skip=("--package",)) + list(extra)
    if "--package" in outs:
        args += ["--apply-to", mesh, "--package", outs["--package"]]
        ins["mesh"] = mesh
    args += ["-j", "1"]
    ins["style"] = style
    return Inv("tambake", "tambake", args, ins, outs, packages=[outs["--package"]] if "--package" in outs else [])


def strokebake(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    ins = {}
    if "growmesh" in inp or "growmesh" in use:
        growmesh = _file(d, inp, "growmesh", "grow.obj", I.obj_text(I.tetra()))
        ref = _ref(d, growmesh)
        doc = I.strokes_with_grow(ref)
        ins["growmesh"] = growmesh
    else:
        doc = I.STROKES
    strokes = _file(d, inp, "strokes", "strokes.json", doc)
    ins["strokes"] = strokes
    outs = _outs(d, "strokebake", out)
    args = [strokes] + _outargs(outs) + ["-j", "1"] + list(extra)
    return Inv("strokebake", "strokebake", args, ins, outs, packages=[outs["-o"]] if "-o" in outs else [])


def _tetra_glb(ctx):
    return ctx.shared_file("tetra.glb", lambda p: I.write(p, I.glb_of(I.tetra())))


def _copy(src, dst):
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    shutil.copyfile(src, dst)
    return dst


def bakeplay_render(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    pkg = inp["pkg"] if "pkg" in inp else _copy(_tetra_glb(ctx), os.path.join(d, "pkg.glb"))
    outs = _outs(d, "bakeplay-render", out)
    args = ["render", pkg] + _outargs(outs) + ["--size", "16x16"] + list(extra)
    return Inv("bakeplay-render", "bakeplay", args, {"pkg": pkg}, outs)


def bakeplay_validate(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    pkg = inp["pkg"] if "pkg" in inp else _copy(_tetra_glb(ctx), os.path.join(d, "pkg.glb"))
    outs = _outs(d, "bakeplay-validate", out)
    args = ["validate", pkg] + _outargs(outs) + ["--size", "16"] + list(extra)
    return Inv("bakeplay-validate", "bakeplay", args, {"pkg": pkg}, outs)


def _pipe_scene_files(ctx, inp, recipe):
    d = ctx.dir
    ring = _file(d, inp, "input", "ring.json", I.RING_PROFILE)
    ref = _ref(d, ring)
    scene = _file(d, inp, "scene", "scene.json", I.pipe_scene(ref))
    return scene, ring


def bakepipe_plan(ctx, inp=None, out=None, use=(), extra=()):
    inp = inp or {}
    scene, ring = _pipe_scene_files(ctx, inp, "bakepipe-plan")
    args = ["plan", scene, "--out-dir", os.path.join(ctx.dir, "baked")] + list(extra)
    return Inv("bakepipe-plan", "bakepipe", args, {"scene": scene, "input": ring}, {})


def bakepipe_ninja(ctx, inp=None, out=None, use=(), extra=()):
    inp = inp or {}
    scene, ring = _pipe_scene_files(ctx, inp, "bakepipe-ninja")
    outs = _outs(ctx.dir, "bakepipe-ninja", out)
    args = ["ninja", scene] + _outargs(outs) + ["--out-dir", os.path.join(ctx.dir, "baked")] + list(extra)
    return Inv("bakepipe-ninja", "bakepipe", args, {"scene": scene, "input": ring}, outs)


def ring_package(ctx):
    """The ring baked once by revolbake (for bakepipe assemble): a shared file."""
    def make(path):
        work = path + ".work"
        os.makedirs(work, exist_ok=True)
        prof = I.write(os.path.join(work, "ring.json"), I.RING_PROFILE)
        res = ctx.run_aux("revolbake", [prof, "-o", os.path.join(work, "ring.revolution.glb"), "--resolution", "64",
                                        "-q"])
        if res.rc != 0:
            raise RuntimeError("setup: revolbake of the ring failed: " + res.first_err())
        os.replace(os.path.join(work, "ring.revolution.glb"), path)
    return ctx.shared_file("ring.revolution.glb", make)


def bakepipe_assemble(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    scene, ring = _pipe_scene_files(ctx, {k: v for k, v in inp.items() if k != "pkg"}, "bakepipe-assemble")
    baked = os.path.join(d, "baked")
    pkg = inp["pkg"] if "pkg" in inp else _copy(ring_package(ctx), os.path.join(baked, "ring.revolution.glb"))
    outs = _outs(d, "bakepipe-assemble", out)
    args = ["assemble", scene] + _outargs(outs) + ["--out-dir", baked] + list(extra)
    return Inv("bakepipe-assemble", "bakepipe", args, {"scene": scene, "pkg": pkg}, outs,
               packages=[outs["-o"]] if "-o" in outs else [])


def bakeinfo(ctx, inp=None, out=None, use=(), extra=()):
    d, inp = ctx.dir, inp or {}
    f = inp["file"] if "file" in inp else _copy(_tetra_glb(ctx), os.path.join(d, "pkg.glb"))
    return Inv("bakeinfo", "bakeinfo", [f] + list(extra), {"file": f}, {})


RECIPES = {
    "geobake": geobake, "bakeshape": bakeshape, "revolbake": revolbake, "groovebake": groovebake,
    "tambake": tambake, "strokebake": strokebake, "bakeplay-render": bakeplay_render,
    "bakeplay-validate": bakeplay_validate, "bakepipe-plan": bakepipe_plan, "bakepipe-ninja": bakepipe_ninja,
    "bakepipe-assemble": bakepipe_assemble, "bakeinfo": bakeinfo,
}
