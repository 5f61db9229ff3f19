#!/usr/bin/env bash
# CI: installs the Debian package that ./dev package made, runs the installed shadelab away from the
# checkout (so it can only use what it installed), then removes the package again.
set -euo pipefail
deb=$(ls "${1:-build}"/shadelab_*.deb | head -n 1)
dpkg -i "$deb"
trap 'dpkg -r shadelab >/dev/null' EXIT
work=$(mktemp -d)
cd "$work"
/usr/bin/shadelab --version
/usr/bin/shadelab --size 320x240 --layout compare --output compare.png
/usr/bin/shadelab --playlist lecture --size 160x120 --output lecture/   # the installed presets, by name
/usr/bin/shadelab /usr/share/shadelab/models/lowpoly_gem.gltf --size 160x120 --output gem.png
test -s compare.png && test -s gem.png && test "$(ls lecture/*.png | wc -l)" -ge 10
test -f /usr/share/man/man1/shadelab.1.gz -o -f /usr/share/man/man1/shadelab.1
test -f /usr/share/applications/shadelab.desktop
# The Python module, installed for Debian's python3: a frame as the installed program writes it.
if [ -d /usr/lib/python3/dist-packages/shadelab ]; then
  /usr/bin/python3 - <<'PY'
import numpy, shadelab
assert shadelab.__file__ == "/usr/lib/python3/dist-packages/shadelab/__init__.py", shadelab.__file__
image = shadelab.render(size=(320, 240), layout="compare")
assert numpy.array_equal(image, shadelab.read_png("compare.png")), "shadelab.render differs from the program"
assert shadelab.probe(160, 120, shadelab.data_path("scenes/lecture/06-exponent-32.json"), size=(320, 240))["miss"] is False
PY
  python_module=yes
fi
# The installed GLSL is what it draws with (found beside /usr/bin, nothing of the build compiled in):
# a broken copy there must fail, naming the file.
echo '#error the installed phong.frag is read' >> /usr/share/shadelab/shaders/phong.frag
if /usr/bin/shadelab --shading phong --size 64x64 --output broken.png 2> err.txt; then
  echo "the installed shadelab did not read /usr/share/shadelab/shaders" >&2; exit 1
fi
grep -q "phong.frag" err.txt
if [ -n "${python_module:-}" ]; then  # the module too
  /usr/bin/python3 -c 'import shadelab
try:
    shadelab.render(size=(64, 64), shading="phong")
except shadelab.ShaderError as e:
    assert "phong.frag" in str(e), e
else:
    raise SystemExit("the installed module did not read /usr/share/shadelab/shaders")'
fi
echo "the installed package renders${python_module:+ (the program and the Python module)}: $deb"
