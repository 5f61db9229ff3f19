#!/usr/bin/env python3
"""Writes shadelab.1 (man page, roff) from the program's own --help and --version, so the manual lists
exactly the options of the build it ships with. Usage: make_manpage.py SHADELAB OUTPUT"""
import re
import subprocess
import sys

exe, out = sys.argv[1], sys.argv[2]
version = subprocess.run([exe, "--version"], capture_output=True, text=True, check=True).stdout.split()[-1]
help_text = subprocess.run([exe, "--help"], capture_output=True, text=True, check=True).stdout


def roff(text):
    text = text.replace("\\", "\\e")
    return "\n".join(("\\&" + line) if line.startswith((".", "'")) else line for line in text.split("\n"))


lines = help_text.rstrip("\n").split("\n")
usage = [l for l in lines if l.startswith(("usage:", "       shadelab"))]
rest = lines[len(usage):]
page = [
    '.TH SHADELAB 1 "" "shadelab %s" "User Commands"' % version,
    ".SH NAME",
    "shadelab \\- flat, Gouraud and Phong shading side by side, for lectures",
    ".SH SYNOPSIS",
    ".nf",
    roff("\n".join(re.sub(r"^(usage:|      ) ", "", l) for l in usage)),
    ".fi",
    ".SH DESCRIPTION",
    ".nf",
    roff("\n".join(rest)),
    ".fi",
    ".SH FILES",
    ".TP",
    ".I /usr/share/shadelab/shaders",
    "the GLSL programs (the program also has them built in); \\fB\\-\\-shader\\-dir\\fR reads another folder",
    ".TP",
    ".I /usr/share/shadelab/scenes/lecture",
    "the lecture presets: \\fBshadelab \\-\\-playlist /usr/share/shadelab/scenes/lecture\\fR",
    ".TP",
    ".I /usr/share/shadelab/models",
    "the small models the presets and examples use",
    ".SH SEE ALSO",
    "The README and docs/ of the source, which explain the lecture's formula and every scene field.",
]
with open(out, "w") as f:
    f.write("\n".join(page) + "\n")
