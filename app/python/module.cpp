// The Python module's C++ half, `shadelab._shadelab` (README, "Python"; the Python half is
// shadelab/__init__.py, which turns keyword arguments into the command line's words). Every call parses
// those words with the program's own parser (options/options.hpp), so names, ranges and messages are the
// CLI's; frames are drawn as `shadelab --output` draws them, on one headless context kept by a
// Renderer on a thread of its own (a GL context is current on one thread), with the GIL released.
// Bad input raises shadelab.InputError (a ValueError) with the CLI's one-line message.
#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/message.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/image/image.hpp"
#include "core/probe/probe.hpp"
#include "core/scene/memory_budget.hpp"
#include "core/scene/panel_sections.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/scene_json.hpp"
#include "headless/headless.hpp"
#include "options/options.hpp"
#include "render/shader_library.hpp"
#include "run/reference.hpp"
#include "run/session.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace py = pybind11;

namespace shadelab {
namespace {

// What a call was given: the command line's words (less --output, which the call adds) and, for a
// scene given as a dict, its JSON text and the folder its relative paths are read from.
struct Call {
    std::vector<std::string> args;
    std::optional<std::string> sceneJson;
    std::string baseDir;
};

// The options of a call that produces `output` ("shadelab.png" for a frame the call returns).
Options parseCall(const Call& call, const std::string& output) {
    std::vector<std::string> args = call.args;
    for (const std::string& a : args)
        if (a == "--output" || a == "-o" || a.rfind("--output=", 0) == 0)
            throw InputError(
                "--output: not taken from Python: render, probe and plot return what they make, and "
                "video takes its file as the first argument");
    args.push_back("--output");
    args.push_back(output);
    Options options = parseOptions(args);
    setMemoryBudget(options.maxMemory);
    return options;
}

Scene sceneOf(const Call& call, const Options& options) {
    if (!call.sceneJson) return sceneFromOptions(options);
    Scene scene = parseScene(*call.sceneJson, "scene", call.baseDir);
    applyOverrides(scene, options);
    return scene;
}

// The run modes a call does not do, refused by the flag that asks for them.
void refuseMode(const Options& options, const char* function) {
    const char* flag = options.mode == RunMode::Benchmark        ? "--benchmark"
                       : options.mode == RunMode::TestSuite      ? "--test"
                       : options.mode == RunMode::PlaylistImages ? "--playlist"
                       : options.mode == RunMode::Plot           ? "--plot"
                       : options.mode == RunMode::Info           ? "--info"
                       : options.mode == RunMode::Video          ? "--animate"
                                                                 : "this option";
    throw InputError(std::string(flag) + ": not taken by shadelab." + function + "() (README, \"Python\")");
}

py::array_t<std::uint8_t> toArray(const Image& image) {
    py::array_t<std::uint8_t> array({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(4)});
    std::memcpy(array.mutable_data(), image.rgba.data(), image.rgba.size());
    return array;
}

// An H x W x 3 or 4 uint8 array as an image (alpha 255 where it has none).
Image fromArray(const py::array& array, const char* what) {
    if (!py::isinstance<py::array_t<std::uint8_t>>(array) || array.ndim() != 3 ||
        (array.shape(2) != 3 && array.shape(2) != 4))
        throw InputError(std::string(what) +
                         ": an H x W x 3 or H x W x 4 array of uint8 (as shadelab.render returns), "
                         "not " +
                         std::string(py::str(array.dtype())) + " of shape " +
                         std::string(py::str(py::tuple(
                             py::cast(std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim()))))));
    const auto pixels = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(array);
    const int h = int(array.shape(0)), w = int(array.shape(1)), c = int(array.shape(2));
    Image image(w, h);
    const std::uint8_t* src = pixels.data();
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i) {
        for (int k = 0; k < 4; ++k)
            image.rgba[4 * i + std::size_t(k)] = k < c ? src[std::size_t(c) * i + std::size_t(k)] : 255;
    }
    return image;
}

// One thread that runs the calls handed to it, in order: the thread the GL context is current on.
class GlThread {
public:
    GlThread() : thread_([this] { loop(); }) {}
    ~GlThread() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    // Runs `work` there and waits for it; its exception is thrown here.
    template <typename F>
    auto call(F work) -> decltype(work()) {
        std::packaged_task<decltype(work())()> task(std::move(work));
        auto result = task.get_future();
        {
            std::lock_guard<std::mutex> lock(mutex_);
            jobs_.push_back([&task] { task(); });
        }
        wake_.notify_all();
        return result.get();
    }

private:
    void loop() {
        for (;;) {
            std::function<void()> job;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                wake_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
                if (jobs_.empty()) return;
                job = std::move(jobs_.front());
                jobs_.pop_front();
            }
            job();
        }
    }
    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::function<void()>> jobs_;
    bool stop_ = false;
    std::thread thread_;
};

// shadelab.Renderer's core: one headless context and renderer (HeadlessSession) kept for many frames,
// made at the first frame and again when --backend or --shader-dir changes.
class PyRenderer {
public:
    explicit PyRenderer(std::string shaderDir) : defaultShaderDir_(std::move(shaderDir)) {}
    ~PyRenderer() { close(); }

    py::array_t<std::uint8_t> render(const Call& call) {
        Image image;
        {
            py::gil_scoped_release released;
            const std::lock_guard<std::mutex> lock(busy_);  // one call at a time (from any Python thread)
            image = frame(call);
        }
        return toArray(image);
    }

    void close() {
        py::gil_scoped_release released;
        const std::lock_guard<std::mutex> lock(busy_);
        if (!gl_) return;
        gl_->call([this] { session_.reset(); });
        gl_.reset();
    }

private:
    Image frame(const Call& call) {
        const Options options = parseCall(call, "shadelab.png");
        if (options.mode != RunMode::Image && options.mode != RunMode::ProbeImage &&
            options.mode != RunMode::SweepSheet)
            refuseMode(options, "render");
        Scene scene = sceneOf(call, options);
        if (options.probe) checkProbePixel(scene, options.probe->x, options.probe->y, "--probe");
        const std::string shaderDir = options.shaderDir.empty() ? defaultShaderDir_ : options.shaderDir;
        if (options.mode == RunMode::SweepSheet) {
            // A sheet is drawn on a context of its own, on a thread of its own (this one's stays current).
            return std::async(std::launch::async,
                              [&] {
                                  return renderSweepHeadless(scene, options.sweeps, ShaderLibrary(shaderDir),
                                                             headlessBackend(options), "--sweep",
                                                             headlessMsaa(options));
                              })
                .get();
        }
        if (!gl_) gl_ = std::make_unique<GlThread>();
        return gl_->call([&] {
            if (!session_ || shaderDir != sessionShaderDir_ || options.backend != sessionBackend_) {
                session_.reset();
                session_ = std::make_unique<HeadlessSession>(ShaderLibrary(shaderDir), headlessBackend(options),
                                                             scene.width, scene.height);
                sessionShaderDir_ = shaderDir;
                sessionBackend_ = options.backend;
            }
            Image image = session_->render(scene, headlessMsaa(options));
            if (!options.probe) return finishedFrame(options, std::move(image), scene, scene.title);
            const auto geometry = session_->geometry();
            const ProbeResult probe =
                probePixel(scene, *geometry, SceneRayCaster(scene, *geometry), options.probe->x, options.probe->y);
            return finishedFrame(options, std::move(image), scene, scene.title, &probe);
        });
    }

    std::string defaultShaderDir_;
    std::mutex busy_;
    std::unique_ptr<GlThread> gl_;
    std::unique_ptr<HeadlessSession> session_;  // made, used and released on gl_'s thread
    std::string sessionShaderDir_, sessionBackend_;
};

// --probe X,Y's JSON: the ray cast and the formula's terms on the CPU, as the program prints them.
std::string probe(const Call& call) {
    py::gil_scoped_release released;
    const Options options = parseCall(call, "shadelab.png");
    if (options.mode != RunMode::ProbeImage) refuseMode(options, "probe");
    Scene scene = sceneOf(call, options);
    checkProbePixel(scene, options.probe->x, options.probe->y, "--probe");
    const auto geometry = loadGeometry(options, scene);
    const ProbeResult result =
        probePixel(scene, *geometry, SceneRayCaster(scene, *geometry), options.probe->x, options.probe->y);
    return probeToJson(scene, result);
}

py::array_t<std::uint8_t> plot(const Call& call) {
    Image image;
    {
        py::gil_scoped_release released;
        const Options options = parseCall(call, "plot.png");
        if (options.mode != RunMode::Plot) refuseMode(options, "plot");
        image = plotImage(options, sceneOf(call, options));
    }
    return toArray(image);
}

// --reference's comparison (run/reference.hpp) of two arrays, with --max-diff/--mean-diff/--max-diff-pixels' words
// checked by the parser.
py::dict compare(const py::array& actualArray, const py::array& referenceArray, const std::vector<std::string>& args,
                 float diffFactor) {
    const Image actual = fromArray(actualArray, "image");
    const Image reference = fromArray(referenceArray, "reference");
    std::vector<std::string> words = {"--reference", "reference.png"};
    words.insert(words.end(), args.begin(), args.end());
    const ImageTolerance tolerance = referenceTolerance(parseCall({words, std::nullopt, ""}, "image.png"));
    CompareResult r;
    std::optional<Image> difference;
    {
        py::gil_scoped_release released;
        r = compareImages(actual, reference, 0);
        if (r.sizeMatches) difference = amplifiedDifference(actual, reference, diffFactor);
    }
    py::dict result;
    result["matches"] = tolerance.matches(r);
    result["size_matches"] = r.sizeMatches;
    result["max"] = r.maxDiff;
    result["mean"] = r.meanDiff;
    result["max_diff"] = tolerance.maxDiff;
    result["mean_diff"] = tolerance.meanDiff;
    result["differing_pixels"] = r.differingPixels;
    result["max_diff_pixels"] =
        tolerance.maxDiffPixels ? py::object(py::int_(*tolerance.maxDiffPixels)) : py::object(py::none());
    result["message"] = r.sizeMatches ? describe(r, tolerance)
                                      : "size " + sizeText(actual) + ", the reference's " + sizeText(reference);
    result["difference"] = difference ? py::object(toArray(*difference)) : py::object(py::none());
    return result;
}

#if SHADELAB_HAVE_VIDEO
// --animate ... --output FILE.gif|.mp4|.webm: the program's own run, on a thread of its own (its context
// is current there).
void video(const Call& call, const std::string& output) {
    py::gil_scoped_release released;
    const Options options = parseCall(call, output);
    if (options.mode != RunMode::Video) refuseMode(options, "video");
    checkOutputPath(output, "--output");
    std::async(std::launch::async, [&options] { return runHeadlessMode(options); }).get();
}
#endif

}  // namespace
}  // namespace shadelab

PYBIND11_MODULE(_shadelab, m) {
    using namespace shadelab;
    m.doc() = "shadelab's renderer, probe, plots and image comparison (the C++ half; import shadelab)";
    static py::exception<InputError> inputError(m, "InputError", PyExc_ValueError);
    static py::exception<ShaderError> shaderError(m, "ShaderError", inputError.ptr());
    // NOLINTNEXTLINE(performance-unnecessary-value-param): pybind11 takes a translator of a value
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const ShaderError& e) {
            shaderError(oneLine(joinedLines(e.what())).c_str());
        } catch (const InputError& e) {
            inputError(oneLine(e.what()).c_str());
        }
    });
    py::class_<Call>(m, "Call").def(py::init<std::vector<std::string>, std::optional<std::string>, std::string>(),
                                    py::arg("args"), py::arg("scene_json") = py::none(), py::arg("base_dir") = "");
    py::class_<PyRenderer>(m, "Renderer")
        .def(py::init<std::string>(), py::arg("shader_dir") = "")
        .def("render", &PyRenderer::render)
        .def("close", &PyRenderer::close);
    // The lecture's parameters (core/scene/parameters.hpp), for shadelab.parameters() and the help.
    m.def("parameters", [] {
        py::list rows;
        for (const Parameter* p = parametersBegin(); p != parametersEnd(); ++p) {
            py::dict row;
            row["name"] = p->name;
            row["option"] = p->option;
            row["symbol"] = p->symbol;
            row["label"] = p->label;
            row["section"] = nameOf(kPanelSections, p->section);
            row["range"] = py::make_tuple(p->range.lo, p->range.hi);
            row["slider"] = py::make_tuple(p->slider.lo, p->slider.hi);
            row["scale"] = p->scale == SliderScale::Log ? "log" : "linear";
            row["default"] =
                std::isnan(p->defaultValue) ? py::object(py::none()) : py::object(py::float_(p->defaultValue));
            row["help"] = parameterHelp(*p);
            rows.append(row);
        }
        return rows;
    });
    m.def("probe", &probe);
    m.def("plot", &plot);
    m.def("compare", &compare, py::arg("image"), py::arg("reference"), py::arg("args"), py::arg("diff_factor"));
    m.def("read_png", [](const std::string& path) { return toArray(readPng(path)); });
    m.def("write_png", [](const std::string& path, const py::array& image) {
        const Image pixels = fromArray(image, "image");
        checkOutputPath(path, "path");
        py::gil_scoped_release released;
        writePng(path, pixels, 9);
    });
    m.def("encode_png", [](const py::array& image) {
        const Image pixels = fromArray(image, "image");
        std::string bytes;
        {
            py::gil_scoped_release released;
            bytes = encodePng(pixels);
        }
        return py::bytes(bytes);
    });
#if SHADELAB_HAVE_VIDEO
    m.def("video", &video);
    m.attr("has_video") = true;
#else
    m.attr("has_video") = false;
#endif
    m.attr("version") = SHADELAB_VERSION;
}
