"""The Python module against the program (README, "Python"): render and probe give what `shadelab ...
--output` writes and `--probe` prints, pixel for pixel and number for number; options by the CLI's names;
scenes as paths, dicts and None; bad input raises InputError (a ValueError) with the CLI's line.
Run by ctest (tests/CMakeLists.txt) with /usr/bin/python3 -m pytest; SHADELAB_EXE names the program and
PYTHONPATH the build's python/ folder."""
import json
import os
import subprocess
import sys
import threading

import numpy as np
import pytest

import shadelab

EXE = os.environ["SHADELAB_EXE"]
SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
LECTURE = os.path.join(SOURCE, "assets", "scenes", "lecture")
MODELS = os.path.join(SOURCE, "assets", "models")


def cli(*args, cwd=None):
    """The program's exit status, stdout and stderr."""
    r = subprocess.run([EXE, *args], capture_output=True, text=True, cwd=cwd)
    return r.returncode, r.stdout, r.stderr


def cli_image(tmp_path, *args, cwd=None):
    out = str(tmp_path / "cli.png")
    status, _, err = cli(*args, "--output", out, cwd=cwd)
    assert status == 0, err
    return shadelab.read_png(out)


# (keyword arguments, the same as the command line's words; the scene first where there is one)
CASES = [
    ({"size": (160, 120)}, ["--size", "160x120"]),
    ({"size": (320, 240), "layout": "compare", "ke": 128}, ["--size", "320x240", "--layout", "compare", "--ke", "128"]),
    ({"scene": os.path.join(LECTURE, "14-all-terms.json"), "size": (200, 150)},
     [os.path.join(LECTURE, "14-all-terms.json"), "--size", "200x150"]),
    ({"scene": os.path.join(MODELS, "lowpoly_gem.gltf"), "size": (160, 120), "shading": "flat"},
     [os.path.join(MODELS, "lowpoly_gem.gltf"), "--size", "160x120", "--shading", "flat"]),
    ({"size": (240, 160), "mesh": "icosphere:2", "light": ["point:-4,3,2", "directional:1,-1,0:color=0.2,0.4,1"],
      "color": (1, 0.5, 0.2), "shading": "gouraud"},
     ["--size", "240x160", "--mesh", "icosphere:2", "--light", "point:-4,3,2", "--light",
      "directional:1,-1,0:color=0.2,0.4,1", "--color", "1,0.5,0.2", "--shading", "gouraud"]),
    ({"size": (320, 200), "layout": "diff", "diff": "gouraud,phong", "ks": 0.8, "formula": True, "captions": True},
     ["--size", "320x200", "--layout", "diff", "--diff", "gouraud,phong", "--ks", "0.8", "--formula", "--captions"]),
    ({"size": (320, 240), "mesh": "icosphere:2", "probe": (160, 120), "formula": True},
     ["--size", "320x240", "--mesh", "icosphere:2", "--probe", "160,120", "--formula"]),
    ({"size": (96, 72), "sweep": "ke=8,64"}, ["--size", "96x72", "--sweep", "ke=8,64"]),
    ({"size": (160, 120), "msaa": 4, "reflection": "blinn-phong"},
     ["--size", "160x120", "--msaa", "4", "--reflection", "blinn-phong"]),
]


@pytest.mark.parametrize("kwargs,words", CASES, ids=[" ".join(w[-4:]) for _, w in CASES])
def test_render_is_what_the_program_writes(tmp_path, kwargs, words):
    kwargs = dict(kwargs)
    scene = kwargs.pop("scene", None)
    image = shadelab.render(scene, **kwargs)
    expected = cli_image(tmp_path, *words)
    assert image.dtype == np.uint8 and image.shape == expected.shape and image.shape[2] == 4
    assert np.array_equal(image, expected), "differs at %d pixels" % int((image != expected).any(axis=2).sum())


def test_a_renderer_keeps_its_context_for_many_frames(tmp_path):
    # sizes and meshes change between frames; each frame is still the program's
    with shadelab.Renderer() as r:
        frames = [(r.render(size=(160, 120), ke=k), ["--size", "160x120", "--ke", str(k)]) for k in (8, 64)]
        frames.append((r.render(size=(200, 100), mesh="torus"), ["--size", "200x100", "--mesh", "torus"]))
        frames.append((r.render(size=(160, 120)), ["--size", "160x120"]))
    for image, words in frames:
        assert np.array_equal(image, cli_image(tmp_path, *words))


def test_a_dict_scene_is_the_scene_file(tmp_path):
    path = os.path.join(LECTURE, "15-coloured-lights.json")
    with open(path) as f:
        scene = json.load(f)
    assert np.array_equal(shadelab.render(scene, size=(160, 120)), cli_image(tmp_path, path, "--size", "160x120"))
    # one written by hand, with a relative model path read from the working folder
    scene = {"objects": [{"mesh": {"type": "gltf", "path": "lowpoly_gem.gltf"}, "material": {"ke": 64, "ks": 0.9}}],
             "layout": "compare"}
    file = tmp_path / "gem.json"
    file.write_text(json.dumps(scene))
    cwd = os.getcwd()
    os.chdir(MODELS)
    try:
        image = shadelab.render(scene, size=(240, 100))
    finally:
        os.chdir(cwd)
    status, _, err = cli(str(file), "--size", "240x100", "--output", str(tmp_path / "x.png"))
    assert status == 2 and "lowpoly_gem.gltf" in err  # (from tmp_path the relative path is not there)
    file.write_text(json.dumps({**scene, "objects": [{**scene["objects"][0], "mesh": {
        "type": "gltf", "path": os.path.join(MODELS, "lowpoly_gem.gltf")}}]}))
    assert np.array_equal(image, cli_image(tmp_path, str(file), "--size", "240x100"))


@pytest.mark.parametrize("where,words", [
    ((200, 150), ["--mesh", "icosphere:2", "--light", "point:-4,3,2", "--size", "400x300"]),
    ((20, 20), ["--size", "400x300"]),  # a miss
    ((300, 100), [os.path.join(LECTURE, "03-gouraud-misses-highlight.json"), "--size", "640x360"]),
])
def test_probe_is_what_the_program_prints(tmp_path, where, words):
    status, out, err = cli(*words, "--probe", "%d,%d" % where, "--output", str(tmp_path / "p.png"))
    assert status == 0, err
    scene = words[0] if words[0].endswith(".json") else None
    rest = words[1:] if scene else words
    options = {rest[i][2:]: rest[i + 1] for i in range(0, len(rest), 2)}
    assert shadelab.probe(*where, scene, **options) == json.loads(out)


@pytest.mark.parametrize("kind,options,words", [
    ("fresnel", {"ior": 1.5}, ["--ior", "1.5"]),
    ("lobe", {"size": (400, 300), "ke": 16}, ["--size", "400x300", "--ke", "16"]),
])
def test_plot_is_what_the_program_writes(tmp_path, kind, options, words):
    assert np.array_equal(shadelab.plot(kind, **options), cli_image(tmp_path, "--plot", kind, *words))


def cli_error(*words):
    status, _, err = cli(*words, "--output", "/tmp/never-written.png")
    assert status == 2
    assert err.startswith("shadelab: ") and err.count("\n") == 1
    return err[len("shadelab: "):].rstrip("\n")


@pytest.mark.parametrize("kwargs,words", [
    ({"ka": "abc"}, ["--ka", "abc"]),
    ({"ke": -3}, ["--ke", "-3"]),
    ({"size": "10x"}, ["--size", "10x"]),
    ({"shading": "toon"}, ["--shading", "toon"]),
    ({"no_such_option": 1}, ["--no-such-option", "1"]),
    ({"frames": 3}, ["--frames", "3"]),
    ({"scene": "/nonexistent/scene.json"}, ["/nonexistent/scene.json"]),
    ({"light": "point:1,2"}, ["--light", "point:1,2"]),
])
def test_bad_input_raises_the_programs_message(kwargs, words):
    kwargs = dict(kwargs)
    scene = kwargs.pop("scene", None)
    with pytest.raises(ValueError) as e:
        shadelab.render(scene, **kwargs)
    assert isinstance(e.value, shadelab.InputError)
    assert str(e.value) == cli_error(*words)


def test_bad_dict_scenes_and_arguments():
    with pytest.raises(shadelab.InputError, match="ka"):
        shadelab.render({"objects": [{"mesh": {"type": "icosphere"}, "material": {"ka": "much"}}]})
    with pytest.raises(shadelab.InputError):
        shadelab.render({"layout": 3})
    with pytest.raises(shadelab.InputError, match="--benchmark"):
        shadelab.render(benchmark=5)
    with pytest.raises(shadelab.InputError, match="--output"):
        shadelab.render(output="x.png")
    with pytest.raises(shadelab.InputError, match="--probe"):
        shadelab.probe(5000, 10, size=(64, 64))
    with pytest.raises(shadelab.InputError, match="--plot"):
        shadelab.plot("nonsense")
    with pytest.raises(shadelab.InputError):
        shadelab.compare(np.zeros((4, 4), np.uint8), np.zeros((4, 4, 4), np.uint8))
    with pytest.raises(shadelab.InputError, match="--max-diff"):
        shadelab.compare(np.zeros((4, 4, 4), np.uint8), np.zeros((4, 4, 4), np.uint8), max_diff=300)
    assert shadelab.render(size=(32, 24)).shape == (24, 32, 4)  # and the module goes on


def test_a_shader_that_does_not_compile(tmp_path):
    for name in os.listdir(os.path.join(SOURCE, "shaders")):
        with open(os.path.join(SOURCE, "shaders", name)) as f:
            (tmp_path / name).write_text(f.read())
    with open(tmp_path / "phong.frag", "a") as f:
        f.write("\n#error the broken phong.frag\n")
    with shadelab.Renderer() as r:
        with pytest.raises(shadelab.ShaderError, match="phong.frag") as e:
            r.render(size=(32, 24), shading="phong", shader_dir=str(tmp_path))
        assert isinstance(e.value, ValueError) and "\n" not in str(e.value)
        assert r.render(size=(32, 24), shading="flat", shader_dir=str(tmp_path)).shape == (24, 32, 4)


def test_compare_is_the_references_comparison(tmp_path):
    image = shadelab.render(size=(160, 120))
    assert shadelab.compare(image, image.copy()).matches
    changed = image.copy()
    changed[10:20, 10:20, 0] ^= 0x40  # 64/255 in red at 100 pixels
    shadelab.write_png(tmp_path / "ref.png", changed)
    r = shadelab.compare(image, tmp_path / "ref.png")
    status, out, _ = cli("--size", "160x120", "--output", str(tmp_path / "a.png"), "--reference",
                         str(tmp_path / "ref.png"))
    assert status == 1 and not r and r.max == 64
    assert r.message in out and out.rstrip().endswith("differs")
    assert r.difference.shape == image.shape and r.difference[15, 15, 0] == 255 and r.difference[50, 50, 0] == 0
    assert shadelab.compare(image, changed, max_diff=64, mean_diff=0.5).matches
    assert r.differing_pixels == 100 and r.max_diff_pixels is None
    loose = dict(max_diff=64, mean_diff=0.5)
    assert shadelab.compare(image, changed, max_diff_pixels=100, **loose).matches
    few = shadelab.compare(image, changed, max_diff_pixels=99, **loose)
    assert not few and few.max_diff_pixels == 99
    status, out, _ = cli("--size", "160x120", "--output", str(tmp_path / "a.png"), "--reference",
                         str(tmp_path / "ref.png"), "--max-diff", "64", "--mean-diff", "0.5", "--max-diff-pixels", "99")
    assert status == 1 and few.message in out
    assert not shadelab.compare(image, image[:, :100]).size_matches
    assert shadelab.compare(image[:, :, :3], image).matches  # RGB against RGBA: alpha 255


def test_the_gil_is_released_while_drawing():
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(1)
            stop.wait(0.0005)  # (sleeps without the GIL)

    old = sys.getswitchinterval()
    sys.setswitchinterval(100.0)  # this thread keeps the GIL unless a call lets go of it
    t = threading.Thread(target=tick)
    t.start()
    try:
        with shadelab.Renderer() as r:  # a new context: the first frame takes a while
            before = len(ticks)
            r.render(size=(320, 240), layout="compare")
            during = len(ticks) - before
    finally:
        stop.set()
        sys.setswitchinterval(old)
        t.join()
    assert during > 0


def test_renderers_on_threads():
    # a renderer each, and one shared by several threads (its calls one at a time)
    own, shared = {}, {}
    shared_renderer = shadelab.Renderer()

    def work(k):
        with shadelab.Renderer() as r:
            own[k] = r.render(size=(96, 64), ke=k)
        shared[k] = shared_renderer.render(size=(96, 64), ke=k)

    threads = [threading.Thread(target=work, args=(k,)) for k in (4, 16, 64, 256)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    shared_renderer.close()
    for k in (4, 16, 64, 256):
        expected = shadelab.render(size=(96, 64), ke=k)
        assert np.array_equal(own[k], expected) and np.array_equal(shared[k], expected)


@pytest.mark.skipif(not shadelab.has_video, reason="this build has no video encoding (SHADELAB_VIDEO)")
def test_video_is_what_the_program_writes(tmp_path):
    words = ["--size", "64x48", "--animate", "ke=4..64:1", "--fps", "4"]
    shadelab.video(tmp_path / "py.gif", size=(64, 48), animate="ke=4..64:1", fps=4)
    status, _, err = cli(*words, "--output", str(tmp_path / "cli.gif"))
    assert status == 0, err
    assert (tmp_path / "py.gif").read_bytes() == (tmp_path / "cli.gif").read_bytes()


def test_parameters_are_the_programs_table():
    """shadelab.parameters() is the program's parameter table: each option's range is the one the program
    refuses past (its message names it), and render()'s help lists the keyword that sets it."""
    rows = {p["name"]: p for p in shadelab.parameters()}
    ke = rows["ke"]
    assert (ke["option"], ke["symbol"], ke["scale"], ke["default"]) == ("--ke", "k_e", "log", 32.0)
    for p in rows.values():
        assert p["slider"][0] >= p["range"][0] and p["slider"][1] <= p["range"][1], p["name"]
        if not p["option"] or p["name"] in ("color", "specular_color", "ambient", "background", "anisotropy"):
            continue
        status, _, err = cli("--" + p["option"][2:], repr(p["range"][1] * 2 + 1), "--info")
        assert status == 2 and p["option"] in err, (p["name"], err)
        assert "      %s (" % p["option"][2:].replace("-", "_") in shadelab.render.__doc__, p["name"]
