// GL tier: every program compiles and links on an OpenGL 3.3 core context, agrees with the C++ side
// on locations, bindings and std140 layout, reports errors with file and line, and draws without
// GL errors into any framebuffer it is handed.
#include "gl/gl_test_support.hpp"
#include "headless/headless_context.hpp"
#include "render/gpu_blocks.hpp"
#include "render/offscreen_target.hpp"
#include "render/program.hpp"
#include "render/renderer.hpp"
#include "headless/headless.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace shadelab;

namespace {

class GlContext : public ::testing::Test {
protected:
    void SetUp() override {
        context_ = makeHeadlessContext(test::backendUnderTest(), 64, 64);
        ASSERT_NE(gladLoadGL(context_->getProcAddress()), 0);
    }
    std::unique_ptr<HeadlessContext> context_;
};

GLint uniformOffset(GLuint program, const char* name) {
    const GLuint index = [&] {
        GLuint i = GL_INVALID_INDEX;
        glGetUniformIndices(program, 1, &name, &i);
        return i;
    }();
    EXPECT_NE(index, GL_INVALID_INDEX) << name;
    GLint offset = -1;
    glGetActiveUniformsiv(program, 1, &index, GL_UNIFORM_OFFSET, &offset);
    return offset;
}

}  // namespace

// Every specialisation the renderer can ask for compiles: no lights, the maximum of 16, and each kind.
TEST_F(GlContext, EverySpecialisationCompiles) {
    const ShaderLibrary library;
    Scene scene;
    std::vector<Scene> variants;
    scene.lights.clear();
    variants.push_back(scene);
    scene.lights.assign(SL_MAX_LIGHTS, Light{});
    scene.reflection = ReflectionModel::Phong;
    variants.push_back(scene);
    // Issue 5: every kind and falloff, with and without shadows, each PCF radius; 16 shadowed lights
    // need 16 samplers in the vertex stage too (flat and gouraud light there).
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        Light& light = scene.lights[l];
        light.type = LightType(l % 4);  // point, directional, area, spot
        light.attenuation = l % 2 ? Attenuation::InverseSquare : Attenuation::None;
        light.range = l % 4 == 1 ? 5.0f : 0.0f;
        light.samples = {int(l % 3) + 1, 2};
    }
    variants.push_back(scene);
    for (int pcf = 0; pcf <= kPcfRadiusRange.hi; ++pcf) {
        scene.shadows.enabled = true;
        scene.shadows.pcf = pcf;
        variants.push_back(scene);
    }
    scene.lights.resize(1);
    scene.lights[0].type = LightType::Area;
    scene.lights[0].samples = {kAreaSamplesPerSideRange.hi, kAreaSamplesPerSideRange.hi};
    variants.push_back(scene);
    // Issue 6: lobe normalisation, both Fresnel modes, every isolated term, with shadows and 16 lights.
    scene.lights.assign(SL_MAX_LIGHTS, Light{});
    scene.shadows.enabled = true;
    scene.specularNormalization = SpecularNormalization::Energy;
    for (ReflectionModel model : {ReflectionModel::Phong, ReflectionModel::BlinnPhong})
        for (FresnelMode fresnel : {FresnelMode::Schlick, FresnelMode::Exact}) {
            scene.reflection = model;
            scene.fresnel = fresnel;
            variants.push_back(scene);
        }
    for (ShowTerm term : {ShowTerm::Ambient, ShowTerm::Diffuse, ShowTerm::Specular, ShowTerm::Unlit})
        scene.show = TermView{term, 0}, variants.push_back(scene);
    for (int l : {0, 7, SL_MAX_LIGHTS - 1}) scene.show = TermView{ShowTerm::Light, l}, variants.push_back(scene);
    for (const Scene& v : variants) {
        for (const char* name : {"flat", "gouraud", "phong"}) {
            SCOPED_TRACE(name);
            EXPECT_TRUE(buildProgram(name, library, programDefines(v)));
        }
        EXPECT_TRUE(buildProgram("flat", library, programDefines(v), "flat_packed"));
    }
    EXPECT_TRUE(buildProgram("difference", library, {}, kFullscreenVertex));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// glTF's doubleSided (SL_DOUBLE_SIDED) with every other switch of a draw, in each mode, flat's packed
// vertices included: Gouraud evaluates the formula twice per vertex (for N and -N), so the largest
// case is 16 shadowed lights of every kind; Phong's interpolated inputs take at most
// SL_MAX_INTERPOLATED_LIGHTS lights.
TEST_F(GlContext, DoubleSidedVariantsCompile) {
    Scene few, many;
    many.lights.assign(SL_MAX_LIGHTS, Light{});
    for (std::size_t l = 0; l < many.lights.size(); ++l) many.lights[l].type = LightType(l % 4);
    many.shadows.enabled = true;
    using Variant = ProgramCache::Variant;
    const Variant variants[] = {{false, false, false, false, true}, {false, false, true, false, true},
                                {false, false, true, true, true}, {true, false, false, false, true},
                                {false, true, true, false, true}};
    for (bool packed : {false, true}) {
        ProgramCache cache{ShaderLibrary(), packed};
        for (const Scene* scene : {&few, &many})
            for (const Variant& v : variants)
                for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
                    if (v.interpolatedInputs && (mode != ShadingMode::Phong || scene == &many)) continue;
                    if (packed && mode != ShadingMode::Flat) continue;
                    SCOPED_TRACE(std::string(toString(mode)) + (packed ? " packed" : ""));
                    EXPECT_NE(cache.get(mode, *scene, v), 0u);
                }
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Anisotropic reflection (SL_ANISOTROPY) with every other switch of a draw, in each mode: textured,
// instanced, double-sided, a progressive pass, alpha mask, emission; 16 shadowed lights of every kind
// (the largest Gouraud case) and none. Flat's anisotropic draws never take the packed vertices.
TEST_F(GlContext, AnisotropicVariantsCompile) {
    Scene none, many;
    none.lights.clear();
    many.lights.assign(SL_MAX_LIGHTS, Light{});
    for (std::size_t l = 0; l < many.lights.size(); ++l) many.lights[l].type = LightType(l % 4);
    many.shadows.enabled = true;
    many.specularNormalization = SpecularNormalization::Energy;
    many.fresnel = FresnelMode::Exact;
    using Variant = ProgramCache::Variant;
    std::vector<Variant> variants(6);
    variants[1].textured = true;
    variants[2].textured = variants[2].instanced = variants[2].doubleSided = true;
    variants[3].accumulate = true;
    variants[4].textured = true, variants[4].alphaMode = SL_ALPHA_MASK, variants[4].emissive = variants[4].emissiveTexture = true;
    variants[5].interpolatedInputs = true;  // ignored for anisotropic draws: the plain phong program
    for (Variant& v : variants) v.anisotropic = true;
    for (bool packed : {false, true}) {
        ProgramCache cache{ShaderLibrary(), packed};
        for (const Scene* scene : {&none, &many})
            for (const Variant& v : variants)
                for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
                    SCOPED_TRACE(std::string(toString(mode)) + (packed ? " packed" : ""));
                    EXPECT_NE(cache.get(mode, *scene, v), 0u);
                }
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Mirror and glass (SL_ENVIRONMENT) with other switches of a draw, in each mode: the room with textured,
// instanced and double-sided draws, a progressive pass, anisotropy with an alpha mask and Phong's
// interpolated inputs (ignored: the plain phong program), under 16 shadowed lights with exact Fresnel;
// the sky and the image plain, with Schlick and "show". And the background program of each. (Kept to
// about 20 compiles: each is an LLVM compile on llvmpipe.)
TEST_F(GlContext, EnvironmentVariantsCompile) {
    Scene many, schlick;
    many.lights.assign(SL_MAX_LIGHTS, Light{});
    for (std::size_t l = 0; l < many.lights.size(); ++l) many.lights[l].type = LightType(l % 4);
    many.shadows.enabled = true;
    many.fresnel = FresnelMode::Exact;
    schlick.fresnel = FresnelMode::Schlick;
    schlick.show.term = ShowTerm::Specular;
    using Variant = ProgramCache::Variant;
    std::vector<Variant> variants(5);
    variants[1].textured = variants[1].instanced = variants[1].doubleSided = true;
    variants[2].accumulate = true;
    variants[3].anisotropic = true, variants[3].textured = true, variants[3].alphaMode = SL_ALPHA_MASK;
    variants[4].interpolatedInputs = true;
    ProgramCache cache{ShaderLibrary(), true};
    auto compile = [&](const Scene& scene, Variant v, int kind) {
        v.environment = kind;
        for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
            SCOPED_TRACE(std::string(toString(mode)) + " environment " + std::to_string(kind));
            EXPECT_NE(cache.get(mode, scene, v), 0u);
        }
    };
    for (const Variant& v : variants) compile(many, v, SL_ENVIRONMENT_ROOM);
    for (int kind : {SL_ENVIRONMENT_SKY, SL_ENVIRONMENT_IMAGE}) compile(schlick, Variant{}, kind);
    for (const char* kind : {"SL_ENVIRONMENT 1", "SL_ENVIRONMENT 2", "SL_ENVIRONMENT 3"})
        for (const char* encoding : {"SL_ENCODING SL_ENCODING_LINEAR", "SL_ENCODING SL_ENCODING_SRGB"})
            EXPECT_NE(buildProgram("background", ShaderLibrary(), {kind, encoding}, kFullscreenVertex).get(), 0u) << kind;
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Scenes that use none of issue 6's switches get exactly the defines (so the programs) they had before.
TEST(ProgramDefines, DefaultScenesAreNotSpecialisedForTheLectureSwitches) {
    Scene scene;
    for (const std::string& d : programDefines(scene)) {
        EXPECT_EQ(d.find("SL_SHOW"), std::string::npos) << d;
        EXPECT_EQ(d.find("SL_FRESNEL"), std::string::npos) << d;
        EXPECT_EQ(d.find("SL_SPECULAR_NORMALIZATION"), std::string::npos) << d;
    }
    scene.ior = 2.0f;  // a value, not a switch: a uniform
    scene.layout = Layout::Diff;
    EXPECT_EQ(programDefines(scene), programDefines(Scene{}));
}

TEST_F(GlContext, EveryProgramLinksAndMatchesTheSharedDefinitions) {
    const ShaderLibrary library;  // the built-in copies
    // Three lights of all kinds, Phong's lobe and sRGB output: every input and block member is used.
    Scene scene;
    scene.lights.assign(3, Light{});
    scene.lights[1].attenuation = Attenuation::InverseSquare;
    scene.lights[2].type = LightType::Directional;
    scene.reflection = ReflectionModel::Phong;
    scene.outputEncoding = OutputEncoding::Srgb;
    for (const char* vertex : {"flat", "flat_packed", "gouraud", "phong", "phong_interpolated"}) {
        SCOPED_TRACE(vertex);
        const std::string name = std::string(vertex) == "flat_packed" ? "flat" : vertex;
        const gl::Program p = buildProgram(name, library, programDefines(scene), vertex);
        ASSERT_TRUE(p);
        if (std::string(vertex) == "flat") {  // three vec3s (MeshCache::gpuMesh)
            EXPECT_EQ(glGetAttribLocation(p.get(), "a_posObject"), SL_ATTRIB_POSITION);
            EXPECT_EQ(glGetAttribLocation(p.get(), "a_centroidObject"), SL_ATTRIB_CENTROID);
            EXPECT_EQ(glGetAttribLocation(p.get(), "a_faceNrmObject"), SL_ATTRIB_NORMAL);
        } else if (std::string(vertex) == "flat_packed") {  // two vec4s
            EXPECT_EQ(glGetAttribLocation(p.get(), "a_posCentroidXObject"), SL_ATTRIB_POSITION);
            EXPECT_EQ(glGetAttribLocation(p.get(), "a_centroidYZNormalXYObject"), SL_ATTRIB_CENTROID);
        } else {
            EXPECT_EQ(glGetAttribLocation(p.get(), "a_posObject"), SL_ATTRIB_POSITION);
            EXPECT_EQ(glGetAttribLocation(p.get(), "a_nrmObject"), SL_ATTRIB_NORMAL);
        }
        const GLuint frame = glGetUniformBlockIndex(p.get(), "FrameBlock");
        const GLuint object = glGetUniformBlockIndex(p.get(), "ObjectBlock");
        ASSERT_NE(frame, GL_INVALID_INDEX);
        ASSERT_NE(object, GL_INVALID_INDEX);
        GLint size = 0, binding = -1;
        glGetActiveUniformBlockiv(p.get(), frame, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
        glGetActiveUniformBlockiv(p.get(), frame, GL_UNIFORM_BLOCK_BINDING, &binding);
        EXPECT_EQ(size_t(size), sizeof(gpu::FrameBlock));
        EXPECT_EQ(binding, SL_BINDING_FRAME);
        glGetActiveUniformBlockiv(p.get(), object, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
        glGetActiveUniformBlockiv(p.get(), object, GL_UNIFORM_BLOCK_BINDING, &binding);
        EXPECT_EQ(size_t(size), sizeof(gpu::ObjectBlock));
        EXPECT_EQ(binding, SL_BINDING_OBJECT);
        // The driver's std140 offsets are the ones the C++ mirror assumes.
        EXPECT_EQ(uniformOffset(p.get(), "u_eyeWorld"), GLint(offsetof(gpu::FrameBlock, eyeWorld)));
        EXPECT_EQ(uniformOffset(p.get(), "u_settings"), GLint(offsetof(gpu::FrameBlock, settings)));
        EXPECT_EQ(uniformOffset(p.get(), "u_lights[1].radiance"),
                  GLint(offsetof(gpu::FrameBlock, lights) + sizeof(gpu::LightGpu) + offsetof(gpu::LightGpu, radiance)));
        EXPECT_EQ(uniformOffset(p.get(), "u_coefficients"), GLint(offsetof(gpu::ObjectBlock, coefficients)));
        EXPECT_EQ(uniformOffset(p.get(), "u_modelSettings"), GLint(offsetof(gpu::FrameBlock, modelSettings)));
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
}

TEST_F(GlContext, CompileErrorsNameProgramStageFileAndLine) {
    const auto dir = std::filesystem::temp_directory_path() / "shadelab-broken-shaders";
    std::filesystem::create_directories(dir);
    // Line 3 of phong.frag is broken; everything else comes from the built-in copies.
    std::ofstream(dir / "phong.frag") << "#include \"lighting.glsl\"\nout vec4 o_color;\nvoid main() { o_color = 1.0 +; }\n";
    try {
        buildProgram("phong", ShaderLibrary(dir.string()));
        ADD_FAILURE() << "broken shader compiled";
    } catch (const ShaderError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("program phong, fragment stage"), std::string::npos) << msg;
        EXPECT_NE(msg.find("phong.frag:3"), std::string::npos) << msg;
    }
    std::filesystem::remove_all(dir);
}

// The renderer draws into whatever framebuffer it is handed: a second FBO (an OffscreenTarget) gives the
// same pixels as the context's own target (OSMesa's default framebuffer, or EGL's FBO).
TEST_F(GlContext, RendersIntoAnyFramebufferWithoutGlErrors) {
    Scene scene;
    scene.width = 64;
    scene.height = 64;
    scene.layout = Layout::Compare;
    scene.objects[0].mesh = MeshSpec{};
    scene.objects[0].mesh.slices = 16;
    scene.objects[0].mesh.stacks = 8;
    Renderer renderer(context_->getProcAddress());
    renderer.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(scene)));
    renderer.render(scene, context_->target());
    const Image viaDefault = readPixels(context_->target());

    const OffscreenTarget fbo(64, 64, 0, "the test's framebuffer");
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    EXPECT_EQ(fbo.target().width, 64);
    EXPECT_EQ(fbo.target().height, 64);
    EXPECT_EQ(fbo.samples(), 0);
    renderer.render(scene, fbo.target());
    const Image viaFbo = readPixels(fbo.target());
    EXPECT_EQ(compareImages(viaFbo, viaDefault).maxDiff, 0);
    EXPECT_GT(compareImages(viaFbo, test::filled(64, 64)).differingPixels, 1000u) << "rendered nothing";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// --benchmark's JSON lines: a driver's name is its own text, quotes and backslashes included (it was
// written into the line unescaped), and every field reads back as written.
TEST(BenchmarkJson, IsValidWhateverTheDriverIsCalled) {
    shadelab::BenchmarkResult r;
    r.frames = 7;
    r.triangles = 1234;
    r.width = 64, r.height = 48;
    r.layout = shadelab::Layout::Single;
    r.mode = shadelab::ShadingMode::Gouraud;
    r.medianMs = 1.23456;
    r.glRenderer = "GPU \"X\" C:\\drivers\\x";
    r.backend = "egl";
    const nlohmann::json j = nlohmann::json::parse(shadelab::toJson(r));
    EXPECT_EQ(j.at("gl_renderer"), r.glRenderer);
    EXPECT_EQ(j.at("shading"), "gouraud");
    EXPECT_EQ(j.at("layout"), "single");
    EXPECT_EQ(j.at("size"), nlohmann::json::array({64, 48}));
    EXPECT_EQ(j.at("triangles"), 1234);
    EXPECT_DOUBLE_EQ(j.at("median_ms").get<double>(), 1.235);
}
