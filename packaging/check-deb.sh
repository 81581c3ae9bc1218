#!/usr/bin/env bash
# Unpacks a built lkstudio .deb into a throwaway root and checks that every file lands where
# the desktop expects it, that the metadata validates, that no Qt library is bundled, and
# that the packaged CLI runs against Debian's own Qt. Usage: check-deb.sh PATH.deb
set -euo pipefail
deb=${1:?usage: check-deb.sh PATH.deb}
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
dpkg-deb -x "$deb" "$root"

fail=0
need() {
    if [ -e "$root/$1" ]; then echo "ok      $1"; else echo "MISSING $1"; fail=1; fi
}
id=org.lkservostudio.lkstudio
need usr/bin/lkstudio
need usr/bin/lkctl
need usr/bin/lksim
need usr/share/applications/$id.desktop
need usr/share/metainfo/$id.metainfo.xml
need usr/share/icons/hicolor/scalable/apps/$id.svg
for size in 16 24 32 48 64 128 256; do need usr/share/icons/hicolor/${size}x${size}/apps/$id.png; done
need usr/lib/udev/rules.d/60-lkstudio-rs485.rules
need usr/share/man/man1/lkctl.1.gz
need usr/share/man/man1/lksim.1.gz

desktop-file-validate "$root/usr/share/applications/$id.desktop"
appstreamcli validate --no-net "$root/usr/share/metainfo/$id.metainfo.xml"

if find "$root" -name 'libQt6*' | grep -q .; then
    echo "a Qt library is bundled: Debian provides it"; fail=1
fi
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libqt6core6 libqt6serialport6 libqt6widgets6 libqt6charts6 libqt6svg6 qt6-qpa-plugins; do
    case "$depends" in *"$lib"*) ;; *) echo "Depends lacks $lib"; fail=1 ;; esac
done
"$root/usr/bin/lkctl" --version
"$root/usr/bin/lkctl" encode motor_off --id 1 | grep -qx '3E 80 01 00 BF' || { echo "packaged lkctl does not run"; fail=1; }
[ $fail -eq 0 ] && echo "deb check passed: $(basename "$deb")"
exit $fail
