# shellcheck shell=bash
# Shared set-up for tools/demo and tools/test: picks a Blender (bpy) version,
# finds the Python it needs, makes or reuses a cached virtual environment and
# checks the system libraries bpy loads. Sourced, never run.
#
#   WATER_SURFACE_BLENDER  bpy version: 5.2.3 (default), 4.5.15, 4.2.23
#   WATER_SURFACE_CACHE    where venvs live (default ~/.cache/water_surface)
#   WATER_SURFACE_PYTHON   a Python interpreter to use instead of searching

set -euo pipefail

ws_die() { echo "water_surface: $*" >&2; exit 1; }
ws_say() { echo "water_surface: $*" >&2; }

WS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WS_CACHE="${WATER_SURFACE_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/water_surface}"

# Python minor version each supported bpy is built for.
ws_python_for() {
    case "$1" in
        4.2.23|4.5.15) echo 3.11 ;;
        5.2.3) echo 3.13 ;;
        *) return 1 ;;
    esac
}

# Prints a runnable interpreter of version $1 (e.g. 3.13), or nothing.
# pyenv shims only run when their version is selected, so look inside pyenv too.
ws_find_python() {
    local want="$1" cand root
    local cands=()
    [ -n "${WATER_SURFACE_PYTHON:-}" ] && cands+=("$WATER_SURFACE_PYTHON")
    cands+=("python$want")
    if command -v pyenv >/dev/null 2>&1; then
        root="$(pyenv root 2>/dev/null || true)"
        [ -n "$root" ] && cands+=("$root"/versions/"$want"*/bin/python"$want")
    fi
    cands+=("/usr/bin/python$want" "/usr/local/bin/python$want" python3)
    for cand in "${cands[@]}"; do
        [ -x "$cand" ] || command -v "$cand" >/dev/null 2>&1 || continue
        if [ "$("$cand" -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null)" = "$want" ]; then
            command -v "$cand" 2>/dev/null || echo "$cand"
            return 0
        fi
    done
    return 0
}

# Chooses WS_BLENDER and WS_PY_BIN; the default falls back to 4.5.15 without Python 3.13.
ws_pick_blender() {
    local asked="${WATER_SURFACE_BLENDER:-}"
    WS_BLENDER="${asked:-5.2.3}"
    local minor
    minor="$(ws_python_for "$WS_BLENDER")" ||
        ws_die "unsupported Blender '$WS_BLENDER': pick one of 4.2.23, 4.5.15, 5.2.3 (WATER_SURFACE_BLENDER)"
    WS_PY_BIN="$(ws_find_python "$minor")"
    if [ -z "$WS_PY_BIN" ] && [ -z "$asked" ]; then
        ws_say "no Python 3.13 found, so using Blender 4.5.15 (Python 3.11) instead of 5.2.3; install Python 3.13 for the newest."
        WS_BLENDER=4.5.15
        minor=3.11
        WS_PY_BIN="$(ws_find_python "$minor")"
    fi
    [ -n "$WS_PY_BIN" ] ||
        ws_die "bpy $WS_BLENDER needs Python $minor, which was not found: install python$minor (with venv) or set WATER_SURFACE_PYTHON."
    return 0
}

# Shared libraries bpy needs to load and to render EEVEE through EGL, with their Debian packages.
WS_LIBS=(
    "libX11.so.6:libx11-6" "libXi.so.6:libxi6" "libXxf86vm.so.1:libxxf86vm1"
    "libXfixes.so.3:libxfixes3" "libXrender.so.1:libxrender1" "libxkbcommon.so.0:libxkbcommon0"
    "libSM.so.6:libsm6" "libICE.so.6:libice6" "libGL.so.1:libgl1" "libEGL.so.1:libegl1"
    "libEGL_mesa.so.0:libegl-mesa0" "libgbm.so.1:libgbm1"
)

ws_check_system_libs() {
    local missing=() entry lib pkg
    local have
    have="$(ldconfig -p 2>/dev/null || /sbin/ldconfig -p 2>/dev/null || true)"
    for entry in "${WS_LIBS[@]}"; do
        lib="${entry%%:*}"
        pkg="${entry##*:}"
        grep -q "$lib" <<<"$have" || missing+=("$pkg")
    done
    # Mesa's software rasteriser (swrast/llvmpipe) comes with the DRI drivers.
    if ! compgen -G "/usr/lib/*/dri/swrast_dri.so" >/dev/null && ! compgen -G "/usr/lib*/dri/swrast_dri.so" >/dev/null; then
        missing+=("libgl1-mesa-dri")
    fi
    [ ${#missing[@]} -eq 0 ] && return 0
    local cmd="apt-get install -y --no-install-recommends ${missing[*]}"
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        ws_say "installing system libraries bpy needs: ${missing[*]}"
        { apt-get update -q && DEBIAN_FRONTEND=noninteractive $cmd; } >/dev/null 2>&1 ||
            ws_die "could not install ${missing[*]}; run as root: $cmd"
    else
        ws_die "bpy needs system libraries that are missing; run as root: $cmd"
    fi
}

# Makes or reuses $WS_CACHE/venv-bpy-$WS_BLENDER with pinned bpy and the test tools.
ws_venv() {
    local reqs="$WS_ROOT/tools/requirements.txt"
    WS_VENV="$WS_CACHE/venv-bpy-$WS_BLENDER"
    local stamp="$WS_VENV/.water_surface_ready"
    local want
    want="bpy==$WS_BLENDER $(grep -v '^#' "$reqs" | tr '\n' ' ')"
    if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -x "$WS_VENV/bin/python" ]; then
        return 0
    fi
    mkdir -p "$WS_CACHE"
    local log="$WS_CACHE/install-$WS_BLENDER.log"
    if [ ! -x "$WS_VENV/bin/python" ]; then
        ws_say "creating $WS_VENV with $WS_PY_BIN"
        "$WS_PY_BIN" -m venv "$WS_VENV" >"$log" 2>&1 ||
            ws_die "could not create a venv with $WS_PY_BIN (see $log): install the python venv module."
    fi
    ws_say "installing bpy==$WS_BLENDER and test tools (about 800 MB the first time; log: $log)"
    "$WS_VENV/bin/python" -m pip install -q --disable-pip-version-check \
        "bpy==$WS_BLENDER" -r "$reqs" >>"$log" 2>&1 ||
        ws_die "could not download bpy==$WS_BLENDER from PyPI (see $log): check the network or pip's proxy settings."
    echo "$want" >"$stamp"
}

ws_setup() {
    ws_pick_blender
    ws_check_system_libs
    ws_venv
    WS_PY="$WS_VENV/bin/python"
    export WS_BLENDER WS_PY
}
