#!/bin/sh
# Runs every test function of a QtTest executable on its own (`./tst_x function`), so that a
# function relying on state left by an earlier one shows up. Usage:
#   QT_QPA_PLATFORM=offscreen tests/run-each-function.sh build/tests/ui/panels/tst_mainwindow ...
# Prints one line per function and exits non-zero when any failed.
status=0
for binary in "$@"; do
    for fn in $("$binary" -functions | sed 's/()$//'); do
        if "$binary" "$fn" >/tmp/run-each-function.$$ 2>&1; then
            echo "PASS $(basename "$binary") $fn"
        else
            echo "FAIL $(basename "$binary") $fn"
            sed -n '/^FAIL/,+3p' /tmp/run-each-function.$$
            status=1
        fi
    done
done
rm -f /tmp/run-each-function.$$
exit $status
