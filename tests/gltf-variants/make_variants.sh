#!/usr/bin/env bash
# Regenerates the compressed, quantized and instanced glTF files in this folder with the tools people
# use (npm: gltfpack 1.3, @gltf-transform/cli 4.5; `npm install -g gltfpack @gltf-transform/cli
# gltf-validator`). Sources: the project's own models (assets/models/) and, for the real-model
# variants, ../shared/assets/gltf (made by others, read from there). The outputs are small and kept in
# the repository, so the tests need neither the tools nor ../shared; variants.txt pairs each with its
# original for tests/gl/variants_test.cpp. Every output is checked by the Khronos validator.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
shared=$(cd "$root/.." && pwd)/shared/assets/gltf/sample-assets
models=$root/assets/models
cd "$here"
rm -f ./*.glb ./*.gltf ./*.bin

# name <- command; each variant of the gem and of the torus (no normals: shadelab computes them)
for m in lowpoly_gem coarse_torus_no_normals; do
  src=$models/$m.gltf
  gltfpack -i "$src" -o "${m}.gltfpack.glb"                   # KHR_mesh_quantization (gltfpack's default)
  gltfpack -i "$src" -o "${m}.gltfpack-c.glb" -c              # + EXT_meshopt_compression
  gltfpack -i "$src" -o "${m}.gltfpack-cc.glb" -cc            # + meshopt filters (octahedral normals)
  gltfpack -i "$src" -o "${m}.gltfpack-noq-c.glb" -noq -c     # meshopt on float data
  gltf-transform quantize "$src" "${m}.transform-quantize.glb"
  gltf-transform meshopt "$src" "${m}.transform-meshopt.glb"
  gltf-transform draco "$src" "${m}.transform-draco.glb"
done
# The textured globe: quantized texture coordinates (gltfpack carries their dequantization in a
# KHR_texture_transform) and colours, the image moved into the .glb's buffer.
src=$models/checker_globe.gltf
gltfpack -i "$src" -o checker_globe.gltfpack-c.glb -c
gltf-transform quantize "$src" checker_globe.transform-quantize.glb
gltf-transform draco "$src" checker_globe.transform-draco.glb
# Real models: mirrored instances (EXT_mesh_gpu_instancing), and a dense mesh through every codec.
if [ -d "$shared" ]; then
  gltfpack -i "$shared/NegativeScaleTest/glTF/NegativeScaleTest.gltf" -o NegativeScaleTest.gltfpack-mi-c.glb -mi -c
  spheres=$shared/MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf
  gltfpack -i "$spheres" -o MetalRoughSpheresNoTextures.gltfpack-cc.glb -cc
  gltf-transform draco "$shared/OrientationTest/glTF/OrientationTest.gltf" OrientationTest.transform-draco.glb
else
  echo "make_variants.sh: $shared not found: the real-model variants are not remade" >&2
fi
# The Khronos validator (a library on npm: run through node).
validate='const v = require("gltf-validator"); const f = process.argv[1];
v.validateBytes(new Uint8Array(require("fs").readFileSync(f))).then(r => {
  if (r.issues.numErrors) { console.error(f + ": " + r.issues.numErrors + " validator errors"); process.exit(1); }
});'
for f in ./*.glb; do NODE_PATH=$(npm root -g) node -e "$validate" "$f"; done
ls -l ./*.glb
