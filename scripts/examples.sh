#!/usr/bin/env bash
# The main job: installs what is missing, builds the tools, bakes the example scenes of pipelines/
# into out/examples/, describes the packages with bakeinfo, validates them and renders each (and the
# bundled example scene) headless with bakeplay into out/examples/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"
"$here/scripts/build.sh"
bin="${BUILD_DIR:-$here/build}/tools"
out="$here/out/examples"
mkdir -p "$out"
cd "$here/pipelines/example"
for package in *.glb *.ktx2; do
  "$bin/bakeinfo/bakeinfo" "$package"
  echo
done
"$bin/bakeplay/bakeplay" validate -q *.glb
for package in *.glb; do
  "$bin/bakeplay/bakeplay" render -q "$package" -o "$out/${package%.glb}.png"
done

# GeoTextures (pipelines/geodesic): a generated genus-3 pretzel, three exact geodesic fields, one
# picture per material preset.
geo="$here/pipelines/geodesic"
"$bin/bakeshape/bakeshape" pretzel -o "$out/pretzel.glb"
"$bin/geobake/geobake" "$out/pretzel.glb" --sources "$geo/sources.json" --verify 64 \
  --report "$out/pretzel-fields.report.json" -o "$out/pretzel-fields.glb"
"$bin/bakeplay/bakeplay" validate -q "$out/pretzel-fields.glb"
for preset in isolines sand-water moss-granite paint-metal-rust water-lava opacity-front wave-displacement; do
  "$bin/bakeplay/bakeplay" render -q "$out/pretzel-fields.glb" --geotexture "$preset" \
    -o "$out/geodesic-$preset.png"
done

# Revolution mapping (pipelines/revolution): textures made by bakeshape, then a vase, a ring and a
# plate baked from their profiles, each rendered alone and the three together.
rev="$here/pipelines/revolution"
for pattern in glaze bands hammered knurl; do
  "$bin/bakeshape/bakeshape" "$pattern" --resolution 512 -o "$out/$pattern.png" -q
done
"$bin/revolbake/revolbake" "$rev/vase.json" -o "$out/vase.glb" --base-color "$out/glaze.png" \
  --height-map "$out/hammered.png" --height-scale 0.004 --report "$out/vase.report.json"
"$bin/revolbake/revolbake" "$rev/ring.json" -o "$out/ring.glb" --base-color "$out/bands.png" \
  --height-map "$out/knurl.png" --height-scale 0.003 --position 1.3,0,0 --report "$out/ring.report.json"
"$bin/revolbake/revolbake" "$rev/plate.json" -o "$out/plate.glb" --base-color "$out/bands.png" \
  --position -1.6,0,0 --report "$out/plate.report.json"
"$bin/bakeplay/bakeplay" validate -q "$out/vase.glb" "$out/ring.glb" "$out/plate.glb"
for object in vase ring plate; do
  "$bin/bakeplay/bakeplay" render -q "$out/$object.glb" -o "$out/revolution-$object.png"
done
"$bin/bakeplay/bakeplay" render -q "$out/vase.glb" "$out/ring.glb" "$out/plate.glb" --size 1024x512 \
  -o "$out/revolution-scene.png"

# Hatching (pipelines/hatching): tonal art maps by tambake on a torus and the pretzel, drawn together
# and timed beside standard Blinn-Phong shading of the same scene.
hat="$here/pipelines/hatching"
"$bin/bakeshape/bakeshape" torus -o "$out/torus.glb" -q
"$bin/tambake/tambake" "$hat/hatching.json" -o "$out/hatching.ktx2" --apply-to "$out/torus.glb" \
  --package "$out/torus-hatched.glb" --position -2.4,0,0 --report "$out/hatching.report.json"
"$bin/tambake/tambake" "$hat/stippling.json" -o "$out/stippling.ktx2" --apply-to "$out/pretzel.glb" \
  --package "$out/pretzel-stippled.glb" --position 1.6,0,0 --base-colour 1,0.93,0.8 \
  --report "$out/stippling.report.json"
"$bin/bakeplay/bakeplay" validate -q "$out/torus-hatched.glb" "$out/pretzel-stippled.glb"
"$bin/bakeplay/bakeplay" render -q "$out/torus-hatched.glb" "$out/pretzel-stippled.glb" --size 1024x512 \
  --camera -0.1,1.7,6.9:-0.1,0,0 --light -0.5,0.7,0.6 --frames 20 --compare-standard \
  --report "$out/hatching-scene.report.json" -o "$out/hatching-scene.png"

# Grooves (pipelines/grooves): floor tiles with grout, a vinyl record and an engraved plate baked by
# groovebake into groove grids and drawn with the seed's groove shading; the plate is timed beside
# standard Blinn-Phong shading of the same plane.
grv="$here/pipelines/grooves"
for scene in tiles record plate; do
  "$bin/groovebake/groovebake" "$grv/$scene.json" -o "$out/grooves-$scene.glb" --report "$out/grooves-$scene.report.json" -q
done
"$bin/bakeplay/bakeplay" validate -q "$out/grooves-tiles.glb" "$out/grooves-record.glb" "$out/grooves-plate.glb"
"$bin/bakeplay/bakeplay" render -q "$out/grooves-tiles.glb" --size 1024x768 -o "$out/grooves-tiles.png"
"$bin/bakeplay/bakeplay" render -q "$out/grooves-record.glb" --size 1024x768 -o "$out/grooves-record.png"
"$bin/bakeplay/bakeplay" render -q "$out/grooves-plate.glb" --size 1024x768 --frames 10 --compare-standard \
  --report "$out/grooves-plate.render.json" -o "$out/grooves-plate.png"

"$bin/bakeplay/bakeplay" render -q -o "$out/bundled-example.png" --frames 30 --report "$out/bundled-example.report.json"
echo "rendered: $(cd "$out" && ls *.png | tr '\n' ' ')(in out/examples/)"
echo "open a window on a package: $bin/bakeplay/bakeplay view pipelines/example/wavy-grid.glb"
