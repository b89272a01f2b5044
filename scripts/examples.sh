#!/usr/bin/env bash
# The main job: installs what is missing, builds the tools, bakes the example scenes of pipelines/
# into out/examples/ (make -f Makefile.examples: parallel and incremental), describes the packages
# with bakeinfo, validates them and renders each (and the bundled example scene) headless with
# bakeplay into out/examples/; then bakes, assembles and renders the example scene descriptions with
# bakepipe and Ninja.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"
"$here/scripts/build.sh"
bin="$(cd "${BUILD_DIR:-$here/build}" && pwd)/tools"
out="$here/out/examples"
mkdir -p "$out"
cd "$here/pipelines/example"
for package in *.glb *.ktx2; do
  "$bin/bakeinfo/bakeinfo" "$package"
  echo
done

# Every bake and every validation (pipelines/example's packages too) is a rule of Makefile.examples;
# a run after an earlier one re-bakes only what an input change or a rebuilt tool makes out of date.
make -f "$here/Makefile.examples" -j"$(nproc)" --output-sync=target --no-print-directory BIN="$bin" OUT="$out" \
  all validate

for package in *.glb; do
  "$bin/bakeplay/bakeplay" render -q "$package" -o "$out/${package%.glb}.png"
done

# GeoTextures (pipelines/geodesic): three exact geodesic fields on a generated genus-3 pretzel, one
# picture per material preset.
for preset in isolines sand-water moss-granite paint-metal-rust water-lava opacity-front wave-displacement; do
  "$bin/bakeplay/bakeplay" render -q "$out/pretzel-fields.glb" --geotexture "$preset" \
    -o "$out/geodesic-$preset.png"
done
# The waves (amplitude and frequency falling with the distance, C.6.3) reflecting a sky (C.6.4).
"$bin/bakeplay/bakeplay" render -q "$out/pretzel-fields.glb" --geotexture wave-displacement \
  --environment-map "$out/sky.exr" -o "$out/geodesic-wave-sky.png"

# Revolution mapping (pipelines/revolution): a vase, a ring and a plate baked from their profiles with
# textures made by bakeshape, a row of balusters and a ring of self-shadowing knobs (copies of one
# profile in one shape box), each rendered alone and all together.
for object in vase ring plate balusters knobs; do
  "$bin/bakeplay/bakeplay" render -q "$out/$object.glb" -o "$out/revolution-$object.png"
done
"$bin/bakeplay/bakeplay" render -q "$out/vase.glb" "$out/ring.glb" "$out/plate.glb" "$out/balusters.glb" \
  "$out/knobs.glb" --size 1024x512 --camera 0,1.6,6.5:0,0.4,0 -o "$out/revolution-scene.png"

# Hatching (pipelines/hatching): tonal art maps by tambake on a torus and the pretzel, drawn together
# and timed beside standard Blinn-Phong shading of the same scene.
"$bin/bakeplay/bakeplay" render -q "$out/torus-hatched.glb" "$out/pretzel-stippled.glb" --size 1024x512 \
  --camera -0.1,1.7,6.9:-0.1,0,0 --light -0.5,0.7,0.6 --frames 20 --compare-standard \
  --report "$out/hatching-scene.report.json" -o "$out/hatching-scene.png"
# The torus's tones by its threshold texture (fine tone control, Webb et al. 2002): strokes drawn
# whole rather than two layers blended.
"$bin/bakeplay/bakeplay" render -q "$out/torus-hatched.glb" --size 512x512 --camera -2.4,1.2,3.2:-2.4,0,0 \
  --light -0.5,0.7,0.6 --hatching-tone threshold -o "$out/hatching-threshold.png"

# Grooves (pipelines/grooves): floor tiles with grout, a vinyl record and an engraved plate baked by
# groovebake into groove grids and drawn with the seed's groove shading; the plate is timed beside
# standard Blinn-Phong shading of the same plane.
"$bin/bakeplay/bakeplay" render -q "$out/grooves-tiles.glb" --size 1024x768 -o "$out/grooves-tiles.png"
"$bin/bakeplay/bakeplay" render -q "$out/grooves-record.glb" --size 1024x768 -o "$out/grooves-record.png"
"$bin/bakeplay/bakeplay" render -q "$out/grooves-plate.glb" --size 1024x768 --frames 10 --compare-standard \
  --report "$out/grooves-plate.render.json" -o "$out/grooves-plate.png"
# The plate's mirror cuts reflecting a grey-blue room (light from outside the grooves, seed 000 §7).
"$bin/bakeplay/bakeplay" render -q "$out/grooves-plate.glb" --size 1024x768 --environment 0.25,0.27,0.32 \
  -o "$out/grooves-plate-environment.png"
# Close to where a diagonal cut crosses the ring, with the mirror bounces in the crossing traced
# (seed 000 §7 in §6's area-sampled special cases), beside the cheaper default that reflects the room.
crossing=0.1418,0.08,0.035:0.1418,0.1112,0
for model in environment traced; do
  "$bin/bakeplay/bakeplay" render -q "$out/grooves-plate.glb" --size 320x240 --camera "$crossing" \
    --environment 0.25,0.27,0.32 --groove-reflections "$model" -o "$out/grooves-plate-crossing-$model.png"
done
# The fluted column: grooves drawn on a UV-mapped mesh (groovebake --apply-to).
# Seen and lit from -z: the UV seam (where the rings' two ends meet) faces +z.
"$bin/bakeplay/bakeplay" render -q "$out/grooves-column.glb" --size 384x512 --camera -1.1,0.6,-2.6:0,0,0 --light -0.5,0.6,-0.6 \
  -o "$out/grooves-column.png"

# Paintstrokes (pipelines/paintstrokes): fur grown on a torus and a small tree, made by strokebake's
# generators with baked self-shadowing, each rendered alone and the two together.
for object in fur tree; do
  "$bin/bakeplay/bakeplay" render -q "$out/strokes-$object.glb" -o "$out/strokes-$object.png"
done
"$bin/bakeplay/bakeplay" render -q "$out/strokes-fur.glb" "$out/strokes-tree.glb" --size 1024x512 \
  --camera 1.6,0.6,6.5:1.6,0,0 --report "$out/strokes-scene.report.json" -o "$out/strokes-scene.png"

"$bin/bakeplay/bakeplay" render -q -o "$out/bundled-example.png" --frames 30 --report "$out/bundled-example.report.json"

# Scene descriptions (pipelines/*/scene.json): bakepipe plans only what each scene's materials read,
# Ninja bakes, assembles one pruned scene package and validates it (incrementally), and bakeplay draws
# it from the scene's camera into out/examples/scene-<name>.png.
mkdir -p "$out/scenes"
for scene_file in "$here"/pipelines/*/scene.json; do
  scene=$(basename "$(dirname "$scene_file")")
  "$bin/bakepipe/bakepipe" plan "$here/pipelines/$scene/scene.json" --out-dir "$out/scenes/$scene" | sed -n '/# left out/,$p'
  "$bin/bakepipe/bakepipe" ninja "$here/pipelines/$scene/scene.json" --out-dir "$out/scenes/$scene" \
    -o "$out/scenes/$scene.ninja" -q
  ninja -f "$out/scenes/$scene.ninja" --quiet
  size=$(sed -n 's/.*"width": *\([0-9]*\), *"height": *\([0-9]*\).*/\1x\2/p' "$here/pipelines/$scene/scene.json" | head -1)
  "$bin/bakeplay/bakeplay" render -q "$out/scenes/$scene/$scene.glb" --size "$size" -o "$out/scene-$scene.png"
done
echo "rendered: $(cd "$out" && ls *.png | tr '\n' ' ')(in out/examples/)"
echo "open a window on a package: $bin/bakeplay/bakeplay view pipelines/example/wavy-grid.glb"
