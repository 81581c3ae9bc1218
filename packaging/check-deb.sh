#!/usr/bin/env bash
# Unpacks a built lkstudio .deb into a throwaway root and checks that every file lands where
# the desktop expects it, that the metadata validates, that no Qt library is bundled, that the
# binaries are stripped with their symbols in the -dbgsym package beside it, that the packaged
# CLI runs against Debian's own Qt, and that lintian finds no error and no warning that
# packaging/LINTIAN.md does not explain. Usage: check-deb.sh PATH.deb
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
for page in lkctl lksim lkstudio; do need usr/share/man/man1/$page.1.gz; done
need usr/share/doc/lkstudio/copyright
need usr/share/doc/lkstudio/changelog.gz
for doc in ARCHITECTURE CLI CSV ERRATA PROTOCOL RECORDING TESTING V2.35; do need usr/share/doc/lkstudio/$doc.md; done
need usr/share/bash-completion/completions/lkctl
need usr/share/bash-completion/completions/lksim
need "usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)/wireshark/plugins/lkservo.lua"
# The private shared libraries the programs share (RUNPATH $ORIGIN/../lib/<triplet>/lkstudio).
private_libs=(liblkcore.so liblkui.so)
for lib in "${private_libs[@]}"; do need "usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)/lkstudio/$lib"; done

private_dir=usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)/lkstudio
for bin in usr/bin/lkstudio usr/bin/lkctl usr/bin/lksim "${private_libs[@]/#/$private_dir/}"; do
    if file "$root/$bin" | grep -q 'not stripped'; then echo "$bin is not stripped"; fail=1; fi
done
dbgsym=$(dirname "$deb")/$(basename "$deb" .deb | sed 's/^lkstudio_/lkstudio-dbgsym_/').ddeb
if [ -f "$dbgsym" ]; then
    debug_files=$(dpkg-deb -c "$dbgsym" | grep -c '\.debug$' || true)
    echo "ok      $(basename "$dbgsym"): $debug_files debug files"
    expected=$((3 + ${#private_libs[@]}))
    [ "$debug_files" -eq $expected ] || { echo "expected $expected debug files in $dbgsym"; fail=1; }
else
    echo "MISSING $dbgsym (the debug symbols)"; fail=1
fi

desktop-file-validate "$root/usr/share/applications/$id.desktop"
appstreamcli validate --no-net "$root/usr/share/metainfo/$id.metainfo.xml"

if find "$root" -name 'libQt6*' | grep -q .; then
    echo "a Qt library is bundled: Debian provides it"; fail=1
fi
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libqt6core6 libqt6serialport6 libqt6serialbus6 libqt6widgets6 libqt6charts6 libqt6svg6 qt6-qpa-plugins; do
    case "$depends" in *"$lib"*) ;; *) echo "Depends lacks $lib"; fail=1 ;; esac
done
"$root/usr/bin/lkctl" --version
"$root/usr/bin/lkctl" encode motor_off --id 1 | grep -qx '3E 80 01 00 BF' || { echo "packaged lkctl does not run"; fail=1; }

# lintian: errors fail; each warning must be explained in packaging/LINTIAN.md.
lintian_rc=0
lintian_out=$(lintian --fail-on error --tag-display-limit 0 "$deb" 2>&1) || lintian_rc=$?
echo "$lintian_out" | sed 's/^/lintian: /'
if [ $lintian_rc -ne 0 ] || echo "$lintian_out" | grep -q '^E: '; then
    echo "lintian failed (status $lintian_rc)"; fail=1
fi
explained=$(dirname "$0")/LINTIAN.md
for tag in $(echo "$lintian_out" | sed -n 's/^W: [^ ]* \([^ ]*\).*/\1/p' | sort -u); do
    grep -q "\`$tag\`" "$explained" || { echo "lintian warning $tag is not explained in packaging/LINTIAN.md"; fail=1; }
done

size=$(stat -c %s "$deb")
installed=$(dpkg-deb -f "$deb" Installed-Size)
echo "size: $((size / 1024)) KiB .deb, $installed KiB installed"
[ $fail -eq 0 ] && echo "deb check passed: $(basename "$deb")"
exit $fail
