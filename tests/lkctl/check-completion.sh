#!/usr/bin/env bash
# Drives packaging/completion/lkctl the way bash does on TAB and checks what it offers, against
# the lkctl binary given (the completion reads commands and options from lkctl's --help).
# Usage: check-completion.sh COMPLETION_FILE LKCTL_BINARY
set -uo pipefail
completion=$1
lkctl=$2
source /usr/share/bash-completion/bash_completion || { echo "bash-completion is not installed"; exit 1; }
source "$completion"
fail=0

# complete WORD... : what TAB offers after the words (the last one is being typed).
complete_words()
{
    COMP_WORDS=("$lkctl" "$@")
    COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
    COMP_LINE="${COMP_WORDS[*]}"
    COMP_POINT=${#COMP_LINE}
    COMPREPLY=()
    _lkctl lkctl "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
    printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' ' | sed 's/ $//'
}

expect()
{
    local want=$1
    shift
    local got
    got=$(complete_words "$@")
    if [ "$got" = "$want" ]; then
        echo "ok   lkctl $* -> $got"
    else
        echo "FAIL lkctl $*: want '$want', got '$got'"
        fail=1
    fi
}

expect "scan step stop" s
expect "decode" de
expect "--baud --bitrate --can --drives --from --json --port --retries --sim --sim-rom-dir --sweep-bauds --to" scan --
expect "--sweep-bauds" scan --sw
expect "--sim --sim-rom-dir" info 3 --si
expect "115200" scan --baud 1152
expect "multi-turn" read 3 mu
expect "single-position speed" control 3 s
expect "multi-position" control 3 m
expect "multi-torque" control m
expect "increment_position increment_position_limited" encode incr
expect "--speed-dps" encode speed --id 1 --speed-d
expect "can can236" encode speed --link ca
expect "MF MG MH MS" decode --series ""
expect "all" off a
expect "position" step 3 p
expect "--duration" step 3 speed 0 100 --du
expect "speed" freq 3 s
expect "position" freq 3 p
expect "position speed" tune 3 ""
expect "ram" tune 3 speed --write ""
expect "--max-overshoot" tune 3 speed --max-o
expect "ccw cw" control 3 single-position 90 --direction ""
expect "params pid" read 1 p
expect "param pid" write 1 p
expect "max_angle_deg max_speed_dps max_torque" write 1 param max
expect "brake" br
expect "engage" brake 1 e
expect "--motor-off-ok" brake 1 release --mo
expect "clear-errors clear-turns" clear
expect "zero" ze
expect "--ram --rom" zero 3 --r
expect "--yes" clear-turns 1 --y
[ $fail -eq 0 ] && echo "bash completion ok"
exit $fail
