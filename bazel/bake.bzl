"""Bazel rules for the bake toolchain.

bake_asset runs one baker (geobake, groovebake, revolbake, tambake, strokebake, bakeshape) as a Bazel action:

    load("@bake_rules//:bake.bzl", "bake_asset")

    bake_asset(
        name = "tiles",
        src = "tiles.json",
        out = "tiles.glb",
        tool = "@bake_tools//:groovebake",
        options = ["--cell-size", "0.01"],
    )

Bazel has no depfiles: every file an action reads must be declared. `src` is the main input; files
reached through options (a geobake --sources file, a revolbake --height-map, a tambake style's stroke
image, the meshes a strokebake list's generators grow on) go in `data` and are named in `options` with $(location ...). `bakeTOOL ... --print-inputs`
lists what a bake reads. Outputs besides `out` (a tambake --threshold texture) go in `extra_outs` and
are named in `options` with $(location ...) too. The sandbox makes an undeclared input an error rather
than a stale build, and Bazel's own action cache (local or remote) plays the role of --cache-dir.

The tools are labels of prebuilt executables: bake_tools_repository (in the WORKSPACE) makes the
repository @bake_tools whose targets are the installed tools (`cmake --install BUILD --prefix PREFIX`)
under PREFIX/bin, PREFIX taken from the environment variable BAKE_TOOLS_PREFIX or the `prefix`
attribute.
"""

BAKE_TOOLS = ["bakeinfo", "bakeshape", "geobake", "groovebake", "revolbake", "strokebake", "tambake"]

def _bake_asset_impl(ctx):
    outputs = [ctx.outputs.out] + ctx.outputs.extra_outs
    args = ctx.actions.args()
    if ctx.file.src:
        args.add(ctx.file.src)
    args.add("-o", ctx.outputs.out)
    args.add_all([ctx.expand_location(option, ctx.attr.data) for option in ctx.attr.options])
    args.add("-q")
    inputs = ctx.files.data + ([ctx.file.src] if ctx.file.src else [])
    ctx.actions.run(
        executable = ctx.executable.tool,
        arguments = [args],
        inputs = inputs,
        outputs = outputs,
        mnemonic = "Bake",
        progress_message = "Baking %s with %s" % (ctx.outputs.out.short_path, ctx.attr.tool.label.name),
    )
    return [DefaultInfo(files = depset(outputs))]

_bake_asset = rule(
    implementation = _bake_asset_impl,
    doc = "Bakes `src` into `out` (and `extra_outs`) with a baker.",
    attrs = {
        "src": attr.label(allow_single_file = True, doc = "The main input (none for bakeshape)."),
        "out": attr.output(mandatory = True, doc = "The package or texture to write (-o)."),
        "extra_outs": attr.output_list(doc = "Other files the options make the baker write."),
        "data": attr.label_list(allow_files = True, doc = "Other files the bake reads."),
        "options": attr.string_list(doc = "Baker options; $(location) of `data` is expanded."),
        "tool": attr.label(mandatory = True, executable = True, cfg = "exec", allow_files = True, doc = "The baker."),
    },
)

def bake_asset(name, tool, **kwargs):
    """Bakes an asset; `tool` is a baker's name (resolved in @bake_tools) or a label."""
    if tool in BAKE_TOOLS:
        tool = "@bake_tools//:" + tool
    _bake_asset(name = name, tool = tool, **kwargs)

def _bake_tools_repository_impl(rctx):
    prefix = rctx.os.environ.get("BAKE_TOOLS_PREFIX", rctx.attr.prefix)
    found = []
    for tool in BAKE_TOOLS:
        path = rctx.path(prefix + "/bin/" + tool)
        if path.exists:
            rctx.symlink(path, tool)
            found.append(tool)
    if not found:
        fail("no bake tools under %s/bin: install them with `cmake --install BUILD --prefix PREFIX` and set BAKE_TOOLS_PREFIX" % prefix)
    rctx.file("WORKSPACE", "workspace(name = \"%s\")\n" % rctx.name)
    rctx.file("BUILD", "exports_files(%s, visibility = [\"//visibility:public\"])\n" % repr(found))

bake_tools_repository = repository_rule(
    implementation = _bake_tools_repository_impl,
    doc = "The installed bake tools (PREFIX/bin) as the targets @NAME//:geobake, ...",
    attrs = {"prefix": attr.string(default = "/usr/local", doc = "Install prefix when BAKE_TOOLS_PREFIX is unset.")},
    environ = ["BAKE_TOOLS_PREFIX"],
    local = True,
)
