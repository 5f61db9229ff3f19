#pragma once
// RendererOptions: how a renderer is tuned, given at construction (render/renderer.hpp).
#include <cstddef>

namespace shadelab {

// How a renderer is tuned for the way it is used (a one-off frame, the viewer, a benchmark, a test
// that compares two paths). Given at construction; the pictures are the same whatever the choice.
struct RendererOptions {
    // Which program Phong draws use: Uniform, phong.vert and phong.frag, which read the formula's
    // values from the uniform blocks (the files the viewer's Shader view lists, so the viewer uses
    // these); Interpolated, the speed variant shaders/phong_interpolated.vert and .frag, which get
    // them as inputs from the vertex stage; Auto (headless frames) picks the variant for a draw whose
    // triangles cover at least kInputsMinPixelsPerTriangle pixels each (bounding box on screen /
    // front-facing triangles), the blocks otherwise. Tests compare the two.
    enum class PhongInputs { Auto, Interpolated, Uniform };
    PhongInputs phongInputs = PhongInputs::Auto;

    // The order meshes are uploaded in. VertexCache reorders each mesh's triangles and vertices for
    // the driver's vertex cache (render/cpu/vertex_order.hpp): the same picture with up to ~40% fewer
    // vertex-shader runs a frame, for a one-off cost at upload (~0.15 s per million triangles). Worth
    // it for a mesh drawn many times (the viewer, --benchmark), not for one --output frame.
    enum class MeshOrder { AsGiven, VertexCache };
    MeshOrder meshOrder = MeshOrder::AsGiven;

    // Draws of more than this many triangles go in chunks of that many, and after submitting a chunk
    // the renderer waits for the one before it (a fence), so the driver never holds more than two.
    // llvmpipe bins every triangle of what it was given before its threads rasterise, a few scenes of
    // ~36 MiB at a time: a frame of the 2M-triangle sphere raised resident memory by ~100 MiB, in
    // chunks of 250k by ~30 MiB. The waits cost steady frames ~9% (binning and rasterising overlap
    // less), so it is for a one-off frame (headless --output), not the viewer. 0 (the default): off.
    std::size_t drawChunkTriangles = 0;

    // A glTF model's GPU instances (EXT_mesh_gpu_instancing, Mesh::instanced) as instanced draws: one
    // copy of the instanced parts uploaded, drawn once per instance. Off: every instance baked into
    // the vertex buffer, as the CPU side holds them (a test compares the two).
    bool instancedDraws = true;

    // Flat shading's nine floats per vertex (position, centroid, face normal) in two vec4s, drawn by
    // shaders/flat_packed.vert, instead of three vec3s (flat.vert): ~7% off a flat frame at 200k
    // triangles on llvmpipe (bench/README.md). For headless frames; the viewer draws with flat.vert,
    // the file a lecturer reads and edits (F5 reloads it). A test compares the two pixel for pixel.
    bool packedFlatVertices = false;
};

}  // namespace shadelab
