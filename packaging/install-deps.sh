#!/usr/bin/env bash
# Installs what a fresh Debian 12 machine lacks to build, test and run LK Servo Studio.
# Only missing packages are installed; uses sudo when not run as root.
set -euo pipefail

packages=(
    build-essential cmake
    qt6-base-dev qt6-serialport-dev qt6-charts-dev libqt6opengl6-dev qt6-svg-dev
    # CAN through Qt SerialBus; libqt6serialbus6 carries the socketcan and virtualcan plugins
    qt6-serialbus-dev libqt6serialbus6
    qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n
    qt6-qpa-plugins libgl-dev
    clang-format xvfb xauth appstream desktop-file-utils dpkg-dev file go-md2man
    lintian reuse bash-completion
    # tst_wiresharkdissector runs the shipped Lua dissector in tshark
    tshark
    fonts-noto-cjk
    # lkstudio on Wayland (tst_lkstudioprocess starts it under a headless weston)
    qt6-wayland weston
    # the fuzz target (CI builds it with clang and libFuzzer)
    clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -q
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
