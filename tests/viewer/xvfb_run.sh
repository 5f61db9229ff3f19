#!/usr/bin/env bash
# Runs a command inside its own Xvfb X server (1920x1080 unless XVFB_SCREEN, 24-bit colour; Mesa llvmpipe renders).
# Exits 77, which CTest reports as skipped, when xvfb-run or xauth (Debian: xvfb, xauth) is missing.
for tool in xvfb-run xauth; do
  if ! command -v "$tool" >/dev/null; then
    echo "$tool not found (install the Debian packages xvfb and xauth): skipping the real-window test"
    exit 77
  fi
done
# XVFB_SCREEN (default 1920x1080x24) sets the screen; -noreset keeps X resources such as Xft.dpi
# (a 2x content scale for GLFW) after the client that set them disconnects.
exec xvfb-run -a -s "-screen 0 ${XVFB_SCREEN:-1920x1080x24} -noreset" "$@"
