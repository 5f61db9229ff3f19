// What every run mode that loads a scene's models shares (session.hpp).
#include "run/session.hpp"

#include "core/base/message.hpp"

#include <iostream>

namespace shadelab {

void report(const Options& options, const Scene& drawn, const std::vector<GltfInfo>& gltfInfo, std::size_t triangles) {
    for (std::size_t i = 0; i < gltfInfo.size(); ++i) {
        const GltfInfo& info = gltfInfo[i];
        const std::string& path = drawn.objects[i].mesh.resolvedPath;
        for (const std::string& w : info.warnings)
            std::cerr << oneLine("shadelab: warning: " + path + ": " + w) << "\n";
        if (options.verbose && drawn.objects[i].mesh.type == MeshSpec::Type::Gltf) {
            std::cerr << "shadelab: " << path << ": " << info.triangles << " triangles, " << info.generatedNormals
                      << " generated normals";
            if (info.textures) std::cerr << ", " << info.textures << " base colour texture(s)";
            std::cerr << "\n";
        }
    }
    if (options.verbose)
        std::cerr << "shadelab: " << (options.input.empty() ? "built-in default scene" : options.input) << ": "
                  << drawn.objects.size() << " object(s), " << triangles << " triangles\n";
}

std::shared_ptr<SceneGeometry> loadGeometry(const Options& options, Scene& scene) {
    auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
    frameIfNeeded(scene, *geometry);
    report(options, scene, geometry->gltfInfo, geometry->triangleCount());
    return geometry;
}

}  // namespace shadelab
