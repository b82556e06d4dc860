#!/usr/bin/env bash
# Install what b2analytic needs from Debian's packages, and only what is missing.
# Safe to run any number of times: with everything present it installs nothing.
# --fuzz: also clang (libFuzzer and its sanitizers, for scripts/fuzz.sh).
set -euo pipefail

packages=(
	g++ cmake make          # compiler and build system
	libbox2d-dev            # Box2D 2.4.1, the physics engine we extend
	libeigen3-dev           # small dense linear algebra (Newton's Jacobian)
	doctest-dev             # unit tests
	nlohmann-json3-dev      # JSON in and out of the tools, demos and benchmarks
	libcli11-dev            # command lines of the tools, demos and benchmarks
	# The interactive viewer (demos/viewer) and its headless tests:
	pkg-config              # finds Dear ImGui and stb (they ship .pc files, no CMake package)
	libglfw3-dev            # window, OpenGL context, keys and mouse
	libxrandr2 libxinerama1 libxcursor1 libxi6 # X11 extensions GLFW loads at run time (recommended only)
	libimgui-dev            # Dear ImGui with its GLFW and OpenGL 3 back ends, one static library
	libstb-dev              # stb_image_write: the screenshots as PNG (and stb_image, which the tests read them with)
	xvfb xauth              # a virtual X display (xvfb-run) for the headless tests
	libgl1-mesa-dri libglx-mesa0 # Mesa's OpenGL, its software renderer (llvmpipe) included
	libbullet-dev           # Bullet's GJK/EPA, the 3D pair benchmark's baseline (not the library)
)

for arg in "$@"; do
	case "$arg" in
		--fuzz) packages+=(clang libclang-rt-dev) ;; # clang++, and libFuzzer with the sanitizer runtimes (only recommended by clang)
		*) echo "setup: unknown option '$arg' (expected --fuzz)" >&2; exit 2 ;;
	esac
done

missing=()
for p in "${packages[@]}"; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing+=("$p")
	fi
done

if ((${#missing[@]} == 0)); then
	echo "setup: all ${#packages[@]} packages present, nothing to install" >&2
	exit 0
fi

sudo=()
if [ "$(id -u)" -ne 0 ]; then
	sudo=(sudo)
fi
echo "setup: installing ${missing[*]}" >&2
"${sudo[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
