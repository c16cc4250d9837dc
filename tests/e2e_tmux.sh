#!/usr/bin/env bash
# End-to-end run of the real workbench binary in an 80×24 tmux session: switch panes,
# move the roller selection, open the stepper, edit a deck value (valid and invalid),
# export a pane and the report (refusing to replace a file without consent), pin a
# baseline and see the Summary's deltas after an edit, then quit
# through the unsaved-changes prompt. Then, in a shell, each termination signal
# (TERM, INT, HUP, QUIT) sent to the workbench restores the terminal (echo, canonical
# mode, main screen, cursor shown) and exits with 128 + signal. Asserts on
# `tmux capture-pane` text and the pane's flags.
# Exits non-zero on the first failed expectation, printing the screen.
#
# Usage: tests/e2e_tmux.sh            (from anywhere; builds the release binary)
#        ROLLBENCH_BIN=path tests/e2e_tmux.sh   (use an already built binary)
set -euo pipefail

cd "$(dirname "$0")/.."

if ! command -v tmux >/dev/null 2>&1; then
    echo "e2e: tmux missing, installing it" >&2
    if command -v apt-get >/dev/null 2>&1; then
        SUDO=""
        if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then SUDO=sudo; fi
        $SUDO apt-get update -qq >/dev/null
        DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq tmux >/dev/null
    fi
    command -v tmux >/dev/null 2>&1 || { echo "e2e: cannot install tmux" >&2; exit 1; }
fi

if [ -z "${ROLLBENCH_BIN:-}" ]; then
    cargo build --release --quiet --bin rollbench
    TARGET_DIR="${CARGO_TARGET_DIR:-target}"
    case "$TARGET_DIR" in
        /*) ROLLBENCH_BIN="$TARGET_DIR/release/rollbench" ;;   # absolute CARGO_TARGET_DIR
        *) ROLLBENCH_BIN="$(pwd)/$TARGET_DIR/release/rollbench" ;;
    esac
fi
[ -x "$ROLLBENCH_BIN" ] || { echo "e2e: no binary at $ROLLBENCH_BIN" >&2; exit 1; }

SOCK="rollbench-e2e-$$"           # private tmux server: never touches the user's sessions
SESSION="e2e"
WORK="$(mktemp -d)"
cleanup() {
    tmux -L "$SOCK" kill-server >/dev/null 2>&1 || true
    rm -rf "$WORK"
}
trap cleanup EXIT

tm() { tmux -L "$SOCK" "$@"; }
TARGET="$SESSION"                 # the session the helpers below look at
screen() { tm capture-pane -p -t "$TARGET"; }
fail() {
    echo "e2e FAILED: $*" >&2
    echo "----- screen -----" >&2
    screen >&2 || true
    echo "------------------" >&2
    exit 1
}
# wait_for TEXT [SECONDS]: polls the screen until TEXT (fixed string) appears.
wait_for() {
    local text="$1" limit="${2:-15}" i
    for ((i = 0; i < limit * 10; i++)); do
        if screen | grep -qF -- "$text"; then return 0; fi
        sleep 0.1
    done
    fail "expected \"$text\" on screen"
}
# absent TEXT: the screen must not show TEXT.
absent() {
    if screen | grep -qF -- "$1"; then fail "did not expect \"$1\" on screen"; fi
}
keys() { tm send-keys -t "$TARGET" "$@"; sleep 0.15; }
# wait_solved: polls until the status line shows a finished solve. Its form follows the
# width only (issue 30 item 12): "✓ solved in 13 ring + 96 roller iterations, 3.3 ms" from
# 120 columns, "✓ 13 ring + 96 roller it, 3.3 ms" (or "it (warm), …") from 80, "✓ 13+96 it,
# 3.3 ms" below.
wait_solved() {
    local i
    for ((i = 0; i < 150; i++)); do
        if screen | grep -qE -- '✓ (solved in .* iterations[^,]*|.* it( \(warm\))?), [0-9.]+ ms'; then
            return 0
        fi
        sleep 0.1
    done
    fail "expected a finished solve (✓ … it, … ms) on the status line"
}

tm new-session -d -s "$SESSION" -x 80 -y 24 \
    "cd '$WORK' && TERM=xterm-256color '$ROLLBENCH_BIN'; echo \"EXITED:\$?\"; sleep 60"

# 1. Opens on the Inputs pane and solves the default deck.
wait_for "Inputs [US]"
wait_solved
wait_for "Roller count Z"

# 2. Tab to the Summary (the bearing-level answer), Tab to the Rollers table; j j selects
#    roller 3; Enter opens its stepper.
keys Tab
wait_for "L10 reference"
keys Tab
wait_for "Qi lbf"
wait_for "337.5"
keys j j
keys Enter
wait_for "Stepper · roller 3 · step 1/"
keys l l
wait_for "step 3/"
wait_for "resid ax,rad lbf"

# 3. Help overlay lists the keys; any key closes it.
keys '?'
wait_for "key closes"
wait_for "next / previous pane"
keys Space
absent "key closes"

# 4. Back to Inputs, j j selects "Roller length L"; an out-of-range value is refused
#    with the allowed range inline, then a valid one is accepted and solved.
keys 1
keys j j
keys Enter
wait_for "allowed:"
keys End BSpace BSpace BSpace BSpace BSpace BSpace 9 9
keys Enter
wait_for "out of range"
keys Escape
absent "out of range"
keys Enter
keys End BSpace BSpace BSpace BSpace BSpace BSpace 0 . 5 2
keys Enter
wait_for "0.52 in"
wait_for "[+] unsaved"
wait_solved

# 5. Units toggle shows SI values.
keys u
wait_for "Inputs [SI]"
wait_for "0.013208 m"
keys u
wait_for "Inputs [US]"

# 5b. Thermal pane: the node walk of issue 15 (j j k k k k G G k Home End) keeps a node
#     selected and on screen; G shows the last node (oil_cavity) in the list.
keys 5
wait_for "(hottest at the end"
keys j j k k k k G G k Home End
wait_for "bedplate: 86.0"
absent "(hottest at the end"

# 5c. An error is read whole: opening a missing file pops up the whole message; any key
#     closes it, e reopens it; Esc does not quit.
keys o
wait_for "Open deck"
keys n o p e . t o m l Enter
wait_for "No such file or directory (os error 2)"
keys Escape
absent "No such file or directory"
keys e
wait_for "No such file or directory (os error 2)"
keys Escape Escape
absent "No such file or directory"
keys 1
wait_for "Inputs [US]"

# 6. q asks because of the unsaved edit; n stays.
keys q
wait_for "Unsaved changes"
keys n
absent "Unsaved changes"

# 7. Save as (S): the prompt offers deck.toml in the working directory; the saved
#    deck holds the edit and the unsaved marker goes away.
keys S
wait_for "Save deck as"
keys Enter
wait_for "saved deck.toml"
absent "[+] unsaved"
[ -f "$WORK/deck.toml" ] || fail "deck.toml was not written"
grep -q "roller_length = 0.52" "$WORK/deck.toml" || fail "saved deck lacks the edit"

# 8. Undo makes the deck differ from the file again; q asks, y quits cleanly.
keys C-z
wait_for "[+] unsaved"
wait_for "0.5 in"
keys q
wait_for "Unsaved changes"
keys y
wait_for "EXITED:0"
absent "Inputs [US]"      # the alternate screen is gone: terminal restored

# 8b. The tapered roller's Sweep pane fills in while on screen: 21 speeds, counted in the
#     title; an edit of the cone speed re-sweeps (the range follows the deck's speed).
cp decks/trb_afapl.toml "$WORK/trb.toml"
tm new-session -d -s trb -x 80 -y 24 \
    "cd '$WORK' && TERM=xterm-256color '$ROLLBENCH_BIN' trb.toml; echo \"EXITED:\$?\"; sleep 60"
TARGET="trb"
wait_for "Inputs [US]"
wait_solved
keys 6
wait_for "21/21 points"
wait_for "Cone speed"
wait_for "50000"
keys 1
keys /
keys C o n e Space s p e e d Enter
keys Enter
keys End BSpace BSpace BSpace BSpace BSpace BSpace BSpace 8 0 0 0 Enter
wait_for "8000 rpm"
keys 6
wait_for "21/21 points"
wait_for "20000"
absent "50000"
# 8b'. The Study pane (the last of the tapered roller's eight): no study file names this
#      copy of the deck, so the default ±1 % tolerance Monte Carlo of its main keys runs
#      (64 samples) while the pane is on screen; the title counts the points, then the
#      chosen output's histogram and the inputs' sensitivities are drawn; j shows the
#      next output.
keys 8
wait_for "±1 % tolerance study"
wait_for "Study · 64 points" 120
wait_for "equal bins"
wait_for "sensitivity"
keys j
wait_for "output 2/"
keys q
wait_for "Unsaved changes"
keys y
wait_for "EXITED:0"
TARGET="$SESSION"

# 8c. The ball deck's stepper: Enter on the Balls table opens the load distribution's
#     fixed-point steps of the selected ball; l steps forward.
cp decks/chen_b.toml "$WORK/ball.toml"
tm new-session -d -s ball -x 80 -y 24 \
    "cd '$WORK' && TERM=xterm-256color '$ROLLBENCH_BIN' ball.toml; echo \"EXITED:\$?\"; sleep 60"
TARGET="ball"
wait_for "Inputs [SI]"
wait_solved
keys 3
wait_for "Balls"
keys j j
keys Enter
# Ball 3 (balls count from 1 on screen, issue 30 item 9) after two steps down from ball 1.
wait_for "Stepper · ball 3 · step 1/"
wait_for "αi,αo deg"
keys l
wait_for "step 2/"
# The Skid pane: the threshold in the title and marked; an edit re-solves it (a lower
# preload skids earlier) with the pane on screen (the streamed chart, then the solution).
keys 4
wait_for "Skid · skidding from 9780 rpm"
wait_for "threshold"
keys 1
keys /
keys A x i a l Space l o a d Enter
keys Enter
keys End BSpace BSpace BSpace BSpace BSpace BSpace 8 0 0 Enter
wait_for "800 N"
keys 4
wait_for "Skid · skidding from"
wait_for "threshold"
absent "9780 rpm"
# 8d. Export (issue 30 item 20): x on the Balls table offers ball_balls.csv beside the
#     deck and writes every column with its unit in the header; x again asks before
#     replacing the file (any key but y goes back to the prompt, the file kept); X writes
#     the report as `run` writes it (JSON by the offered name's extension).
keys 3
keys x
wait_for "Export the pane to"
wait_for "ball_balls.csv"
keys Enter
wait_for "wrote ball_balls.csv"
[ -f "$WORK/ball_balls.csv" ] || fail "ball_balls.csv was not written"
head -n 1 "$WORK/ball_balls.csv" | grep -qF "Qi N" || fail "the CSV header lacks 'Qi N'"
printf 'keep\n' > "$WORK/ball_balls.csv"
keys x
keys Enter
wait_for "File exists"
keys n
wait_for "Export the pane to"
keys Escape
absent "Export the pane to"
[ "$(cat "$WORK/ball_balls.csv")" = keep ] || fail "the export replaced a file without consent"
keys X
wait_for "Report to"
wait_for "ball_report.json"
keys Enter
wait_for "wrote ball_report" 60
grep -qF '"balls"' "$WORK/ball_report.json" || fail "the report lacks its balls"
# 8e. Baseline (issue 30 item 21): b pins the solution, the status line names it; an edit
#     of the axial load re-solves and the Summary shows Δ lines against the pinned
#     solution; D drops the baseline and the Δ lines go.
keys b
wait_for "baseline: ball.toml (pinned)"
keys 1
keys /
keys A x i a l Space l o a d Enter
keys Enter
keys End BSpace BSpace BSpace BSpace BSpace BSpace 1 2 0 0 Enter
wait_for "1200 N"
wait_solved
keys 2
wait_for "Δ = now − baseline"
for ((i = 0; i < 100; i++)); do
    if screen | grep -qE -- 'Δ [+-][0-9]'; then break; fi
    sleep 0.1
done
screen | grep -qE -- 'Δ [+-][0-9]' || fail "expected a Δ line on the Summary"
wait_for "baseline: ball.toml (pinned)"
#     The Balls table: d shows each cell's change from the baseline, then in %, then the
#     values again; the Skid chart overlays the baseline dimmed.
keys 3
keys d
wait_for "Δ now − baseline"
wait_for "ΔQi N"
keys d
wait_for "Δ % of baseline"
wait_for "ΔQi %"
keys d
wait_for "┌ Balls · columns"
absent "ΔQi"
keys 4
wait_for "baseline (dim)"
keys 2
keys D
wait_for "baseline cleared"
absent "Δ = now − baseline"
absent "baseline: ball.toml"
keys q
wait_for "Unsaved changes"
keys y
wait_for "EXITED:0"
TARGET="$SESSION"

# 9. Signals: the workbench runs in the foreground of an interactive shell; kill -SIG on
#    its pid must leave the terminal as it found it and exit with 128 + signal.
tm new-session -d -s sig -x 80 -y 24 \
    "env -i PATH='$PATH' HOME='$WORK' HISTFILE= TERM=xterm-256color PS1='sh\$ ' bash --norc --noprofile -i"
TARGET="sig"
wait_for 'sh$'
keys "cd '$WORK'" Enter
shell_pid="$(tm list-panes -t sig -F '#{pane_pid}')"
for sig_code in TERM:143 INT:130 HUP:129 QUIT:131; do
    sig="${sig_code%%:*}" code="${sig_code##*:}"
    keys clear Enter
    keys "'$ROLLBENCH_BIN'; echo \"EXITED:\$?\"" Enter
    wait_for "Inputs [US]"
    wait_solved
    pid=""
    for ((i = 0; i < 50; i++)); do
        pid="$(pgrep -P "$shell_pid" | head -n 1 || true)"
        [ -z "$pid" ] || break
        sleep 0.1
    done
    [ -n "$pid" ] || fail "SIG$sig: no workbench process under the shell ($shell_pid)"
    kill "-$sig" "$pid"
    wait_for "EXITED:$code"
    absent "Inputs [US]"
    [ "$(tm display -p -t sig '#{alternate_on}')" = 0 ] || fail "SIG$sig: still in the alternate screen"
    [ "$(tm display -p -t sig '#{cursor_flag}')" = 1 ] || fail "SIG$sig: cursor still hidden"
    keys clear Enter
    keys "stty -a | tr ' ;' '\\n\\n' | grep -xE 'echo|icanon' | sort | tr '\\n' ' '; echo STTY" Enter
    wait_for "echo icanon STTY"
done

echo "e2e: ok"
