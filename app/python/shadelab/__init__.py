"""shadelab from Python: the renderer, the probe, the plots and the image comparison, in-process.

    import shadelab
    image = shadelab.render(size=(320, 240), layout="compare", ke=128)   # H x W x 4 uint8, as --output writes
    terms = shadelab.probe(160, 120, mesh="icosphere:2")                 # --probe X,Y's JSON, as a dict
    curve = shadelab.plot("fresnel", ior=1.5)                            # --plot KIND's image
    result = shadelab.compare(image, "reference.png", max_diff=4)        # --reference's comparison

Keyword arguments are the command line's options by their names (README, "Command line"): `ke=128` is
`--ke 128`, `max_memory="1G"` is `--max-memory 1G`, `captions=True` is `--captions`; a list or tuple of
numbers is one comma-separated value (`color=(1, 0.5, 0.2)`), a list of strings repeats the option
(`light=["point:2,3,2", "point:-2,3,2"]`, `sweep=[...]`). They are read by the program's own parser, so
the names, ranges and messages are the CLI's: bad input raises InputError (a ValueError) with its
one-line message. Frames are drawn on one headless GL context kept for the whole session (Renderer), with
the GIL released while drawing. See README, "Python".
"""

import json
import os

from . import _shadelab
from ._shadelab import InputError, ShaderError

__all__ = ["render", "probe", "plot", "compare", "video", "parameters", "Renderer", "InputError", "ShaderError",
           "read_png", "write_png", "to_png", "data_path", "has_video", "__version__"]
InputError.__module__ = ShaderError.__module__ = "shadelab"
__version__ = _shadelab.version
has_video = _shadelab.has_video


def _data_folder():
    """share/shadelab as the program finds it beside itself: an installed module's
    PREFIX/lib/python3/dist-packages/shadelab -> PREFIX/share/shadelab, a build folder's
    BUILD/python/shadelab -> BUILD/share/shadelab (links to the checkout's shaders/ and assets/). None
    where neither is."""
    here = os.path.dirname(os.path.abspath(__file__))
    for up in (("..", ".."), ("..", "..", "..", "..")):
        folder = os.path.normpath(os.path.join(here, *up, "share", "shadelab"))
        if os.path.isfile(os.path.join(folder, "shaders", "lighting.glsl")):
            return folder
    return None


def data_path(relative):
    """A file of shadelab's data: data_path("scenes/lecture/06-exponent-32.json"), "models/lowpoly_gem.gltf"."""
    folder = _data_folder()
    if folder is None:
        raise InputError("data_path: shadelab's data folder (share/shadelab) is not beside this module")
    path = os.path.join(folder, relative)
    if not os.path.exists(path):
        raise InputError("data_path: " + path + ": no such file")
    return path


def _shader_dir():
    """The GLSL the module reads, as the program does: share/shadelab/shaders (see _data_folder); where
    there is none, the shaders compiled into the module."""
    folder = _data_folder()
    return os.path.join(folder, "shaders") if folder else ""


def _word(value):
    if isinstance(value, (list, tuple)):
        return ",".join(_word(v) for v in value)
    if isinstance(value, float):
        return repr(value)
    return os.fspath(value) if isinstance(value, os.PathLike) else str(value)


def _args(options):
    """The command line's words for keyword arguments (see the module's help)."""
    words = []
    for name, value in options.items():
        flag = "--" + name.replace("_", "-")
        if value is None or value is False:
            continue
        if value is True:
            words.append(flag)
        elif isinstance(value, (list, tuple)) and value and all(isinstance(v, (str, list, tuple)) for v in value):
            for v in value:
                words += [flag, _word(v)]
        else:
            words += [flag, _word(value)]
    return words


def _call(scene, size, options, leading=()):
    """A call's words and scene: a path (scene JSON or glTF), a dict in the scene format, or None."""
    words = list(leading)
    scene_json = None
    if isinstance(scene, dict):
        scene_json = json.dumps(scene)
    elif scene is not None:
        if not isinstance(scene, (str, os.PathLike)):
            raise InputError("scene: a path (scene JSON or glTF), a dict in the scene format or None, not "
                             + type(scene).__name__)
        words.append(os.fspath(scene))
    if size is not None:
        if isinstance(size, (list, tuple)):
            if len(size) != 2:
                raise InputError("size: (width, height), not " + repr(size))
            size = "%sx%s" % tuple(size)
        words += ["--size", str(size)]
    words += _args(options)
    return _shadelab.Call(words, scene_json, os.getcwd())


class Renderer:
    """One headless GL context kept for many frames (its programs stay compiled, a scene's meshes are
    built once while they do not change): what shadelab.render uses. `with shadelab.Renderer() as r:`
    releases the context at the end; close() does too."""

    def __init__(self):
        self._core = _shadelab.Renderer(_shader_dir())

    def render(self, scene=None, *, size=None, **options):
        """The frame `shadelab [SCENE] [options] --output FILE.png` writes, as an H x W x 4 uint8 array."""
        return self._core.render(_call(scene, size, options))

    def close(self):
        self._core.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


_default = None


def render(scene=None, *, size=None, **options):
    """The frame `shadelab [SCENE] [options] --output FILE.png` writes, pixel for pixel, as an H x W x 4
    uint8 array (rows top to bottom, RGBA). `scene`: a scene JSON or glTF path, a dict in the scene format
    (relative paths from the working folder) or None (the built-in scene); `size=(w, h)`; options by the
    CLI's names (shading="phong", layout="compare", ke=128, light=[...], sweep="ke=8,32,128", formula=True,
    probe=(x, y) with formula=True, ...). All calls share one headless context (see Renderer)."""
    global _default
    if _default is None:
        _default = Renderer()
    return _default.render(scene, size=size, **options)


def probe(x, y, scene=None, *, size=None, **options):
    """What `shadelab [SCENE] [options] --probe X,Y --output FILE.png` prints for pixel (x, y): every term
    of the lecture's formula there, as a dict (its JSON). Computed on the CPU; no frame is drawn."""
    return json.loads(_shadelab.probe(_call(scene, size, options, ["--probe", "%d,%d" % (x, y)])))


def plot(kind, scene=None, *, size=None, **options):
    """The image `shadelab [SCENE] --plot KIND [options] --output FILE.png` writes (fresnel, lobe, ...: the
    CLI's --plot names), as an H x W x 4 uint8 array. Drawn on the CPU."""
    return _shadelab.plot(_call(scene, size, options, ["--plot", str(kind)]))


def parameters():
    """The lecture's parameters as the program declares them, once (core/scene/parameters.hpp): a list of
    dicts with name (the scene file's), option (the command line's, "" for none), symbol ("k_e"), label,
    section (the panel's), range, slider and scale (the panel's slider), default (None where it differs
    per component) and help. The keyword argument that sets one is its option's name: ke=128 is --ke 128."""
    return _shadelab.parameters()


def _parameters_help():
    """render()'s list of the parameters that keyword arguments set, made from parameters()."""
    lines = ["", "", "    The lecture's parameters as keyword arguments (shadelab.parameters() has them all):"]
    for p in parameters():
        if not p["option"]:
            continue
        keyword = p["option"][2:].replace("-", "_")
        default = "" if p["default"] is None else ", default %g" % p["default"]
        lines.append("      %s (%s, %g..%g%s): %s" % (keyword, p["symbol"], p["range"][0], p["range"][1], default,
                                                    p["help"]))
    return "\n".join(lines)


class Comparison:
    """What compare() found. `matches`: within max_diff, mean_diff and max_diff_pixels (and of one size);
    `max` (/255) and `mean`: the per-channel differences as --reference measures them; `differing_pixels`:
    the pixels that differ at all; `max_diff_pixels`: the limit (None: none); `difference`: the difference
    amplified as the diff layout shows it (None when the sizes differ); `message`: --reference's words."""

    def __init__(self, d):
        self.__dict__.update(d)

    def __bool__(self):
        return bool(self.matches)

    def __repr__(self):
        return "<shadelab.Comparison %s: %s>" % ("matches" if self.matches else "differs", self.message)


def _image(value, what):
    if isinstance(value, (str, os.PathLike)):
        return _shadelab.read_png(os.fspath(value))
    return value


def compare(image, reference, *, max_diff=None, mean_diff=None, max_diff_pixels=None, diff_factor=4.0):
    """`image` against `reference` (arrays or PNG paths) as `--reference` and `--test` compare: matches when
    no channel of any pixel differs by more than max_diff (/255, default 4), the mean over all channels
    is at most mean_diff (default 0.002) and, given max_diff_pixels, at most that many pixels differ at
    all (--max-diff-pixels). Returns a Comparison (truthy when it matches)."""
    args = _args({"max_diff": max_diff, "mean_diff": mean_diff, "max_diff_pixels": max_diff_pixels})
    return Comparison(_shadelab.compare(_image(image, "image"), _image(reference, "reference"), args,
                                        float(diff_factor)))


def read_png(path):
    """A PNG file as an H x W x 4 uint8 array (InputError when it is missing or not a PNG)."""
    return _shadelab.read_png(os.fspath(path))


def write_png(path, image):
    """Writes an H x W x 3 or 4 uint8 array as a PNG (atomically; the smallest files, for references)."""
    _shadelab.write_png(os.fspath(path), image)


def to_png(image):
    """An H x W x 3 or 4 uint8 array as the bytes of a PNG file (for IPython.display.Image, ipywidgets.Image)."""
    return _shadelab.encode_png(image)


def video(path, scene=None, *, size=None, **options):
    """Writes what `shadelab [SCENE] --animate SPEC [options] --output PATH` writes (.gif, .mp4, .webm):
    give animate="ke:1..256" and the like. Only where the video part is built (has_video); the scene is
    a path or None."""
    if not has_video:
        raise InputError("video: this shadelab was built without video encoding (CMake option SHADELAB_VIDEO)")
    if isinstance(scene, dict):
        raise InputError("video: the scene as a path to its JSON file (a dict is taken by render, probe and plot)")
    _shadelab.video(_call(scene, size, options), os.fspath(path))


render.__doc__ += _parameters_help()
