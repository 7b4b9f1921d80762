#!/usr/bin/env bash
# Runs two builds of the `surftopo` binary on the same meshes and compares the bytes of every
# output file: `quad` with every algorithm, `irreducible` with every algorithm, `delaunay` (the
# triangulation, tessellation, Laplacian and mass matrix). Exits 1 when any output differs.
#
#   scripts/compare_outputs.sh BASE_BIN NEW_BIN MESH...
#
# A way to build the base (e.g. main) beside a checkout, without a second worktree:
#   mkdir -p /tmp/base && git archive main | tar -x -C /tmp/base
#   (cd /tmp/base && cargo build --release -p surftopo-cli)   # /tmp/base/target/release/surftopo
set -euo pipefail
if [ $# -lt 3 ]; then
    echo "usage: $0 BASE_BIN NEW_BIN MESH..." >&2
    exit 2
fi
base=$1 new=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
runs=0 differ=0
# One command on both binaries; every file it writes (named after the binary's side) is compared.
compare() {
    local label=$1
    shift
    local side
    for side in base new; do
        local bin=$base
        [ $side = new ] && bin=$new
        mkdir -p "$work/$side"
        rm -f "$work/$side"/*
        # The arguments name outputs as @NAME: a file of that name in the side's folder.
        local args=()
        local a
        for a in "$@"; do
            case $a in
                @*) args+=("$work/$side/${a#@}") ;;
                *) args+=("$a") ;;
            esac
        done
        "$bin" "${args[@]}" >/dev/null 2>"$work/$side.stderr" || {
            echo "FAIL $label ($side exited $?)"; cat "$work/$side.stderr" >&2; differ=$((differ + 1)); return
        }
    done
    local f
    for f in "$work"/base/*; do
        local name
        name=$(basename "$f")
        local h1 h2
        h1=$(sha256sum <"$f" | cut -c1-16)
        h2=$(sha256sum <"$work/new/$name" | cut -c1-16)
        runs=$((runs + 1))
        if [ "$h1" = "$h2" ]; then
            echo "same   $h1 $label $name"
        else
            echo "DIFFER $h1 $h2 $label $name"
            differ=$((differ + 1))
        fi
    done
}
for mesh in "$@"; do
    m=$(basename "$mesh")
    for alg in sg ps lrs ds ks; do
        compare "$m quad $alg" quad "$mesh" --algorithm "$alg" --seed 7 -o @quads.off
    done
    for alg in rs schipper brute-force; do
        compare "$m irreducible $alg" irreducible "$mesh" --algorithm "$alg" --seed 7 -o @irreducible.off
    done
    compare "$m delaunay" delaunay "$mesh" -o @delaunay.json --tessellation @tessellation.json \
        --laplacian @laplacian.mtx --mass @mass.mtx
done
echo "$runs outputs compared, $differ differ or failed"
[ "$differ" -eq 0 ]
