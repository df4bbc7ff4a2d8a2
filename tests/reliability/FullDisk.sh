#!/bin/bash
# A full disk, on a small tmpfs: during a checkpoint write `lbdem run` exits 1 with one sentence
# (no signal at exit), leaves the previous checkpoint, and a resume from it ends with the files of
# an uninterrupted run; during VTK output it exits 1 with one sentence and leaves no partial
# frame; and the disk pre-check, which counts the second checkpoint of a replacement, refuses a
# disk too small for it. The tmpfs is mounted in a private mount namespace (as root, or as a user
# where unprivileged user namespaces are allowed), so nothing is left mounted; the test is
# skipped (exit 77) only where no tmpfs can be mounted.
# Usage: FullDisk.sh LBDEM CASE WORK_DIR
set -u
lbdem=$(realpath "$1") case=$(realpath "$2") work=$3

if [ -z "${LBDEM_FULL_DISK_NAMESPACE:-}" ]; then
    rm -rf "$work" && mkdir -p "$work" || exit 1
    for flags in "--mount" "--user --map-root-user --mount"; do
        if unshare $flags true 2>/dev/null; then
            LBDEM_FULL_DISK_NAMESPACE=1 exec unshare $flags bash "$0" "$@"
        fi
    done
    echo "skipped: no private mount namespace (not root, no unprivileged user namespaces): cannot mount a small tmpfs"
    exit 77
fi

fail() {
    echo "FAIL: $*"
    exit 1
}
disk=$work/disk
mkdir -p "$disk"
# mount_tmpfs BYTES: a fresh tmpfs of that size on $disk.
mount_tmpfs() {
    umount "$disk" 2>/dev/null
    mount -t tmpfs -o size="$1" tmpfs "$disk" ||
        { echo "skipped: cannot mount a tmpfs of $1 bytes on $disk"; exit 77; }
}
# pages DIR [EXCLUDE_REGEX]: bytes the files under DIR take on a tmpfs (whole 4 KiB pages).
pages() {
    find "$1" -type f -printf '%s %P\n' |
        awk -v exclude="${2:-}" '(exclude == "" || $2 !~ exclude) {
            total += int(($1 + 4095) / 4096) * 4096 } END { print total + 0 }'
}
# expect_one_line FILE PATTERN: FILE holds one line, matching PATTERN (extended regex).
expect_one_line() {
    [ "$(wc -l < "$1")" -eq 1 ] || fail "expected one line on stderr, got: $(cat "$1")"
    grep -Eq "$2" "$1" || fail "stderr does not match '$2': $(cat "$1")"
}
# comparable SUMMARY: summary.json without the timings of the process that wrote it.
comparable() {
    sed '/"stage_seconds"/,/}/d' "$1" | grep -Ev '"(wall_s|mlups)"'
}

small=(--set grains.count=150 --set grains.packing=0.79 --set fluid.enabled=false
       --set run.end_tc=0.1 --set run.output_interval_tc=0.025 --set output.checkpoint_interval_tc=0.05)
dry=("${small[@]}" --set output.vtk=false)

# 1. The disk fills while the second checkpoint is written (the first fits, with every other
#    output of the whole run; the second does not fit beside it). --force: past the pre-check.
"$lbdem" run "$case" "${dry[@]}" --out "$work/whole" --quiet || fail "the reference run failed"
checkpoint=$(pages "$work/whole/checkpoint.h5")
others=$(pages "$work/whole" '^checkpoint')
mount_tmpfs $((others + checkpoint + checkpoint / 2))
"$lbdem" run "$case" "${dry[@]}" --out "$disk/run" --force --quiet 2> "$work/checkpoint.err"
code=$?
[ $code -eq 1 ] || fail "a full disk during a checkpoint: exit $code (expected 1): $(cat "$work/checkpoint.err")"
expect_one_line "$work/checkpoint.err" \
    'checkpoint\.h5: the disk is full; the previous checkpoint is left as it was'
ls "$disk/run" | grep -q tmp && fail "temporary files left: $(ls "$disk/run")"
cp -a "$disk/run" "$work/resumed"
"$lbdem" resume "$work/resumed" --quiet || fail "resume from the checkpoint left by the full disk failed"
cmp "$work/whole/timeseries.csv" "$work/resumed/timeseries.csv" ||
    fail "the resumed run's timeseries.csv differs from the uninterrupted run's"
diff <(comparable "$work/whole/summary.json") <(comparable "$work/resumed/summary.json") ||
    fail "the resumed run's summary.json differs from the uninterrupted run's"
echo "ok: full disk during a checkpoint: exit 1, one sentence, previous checkpoint resumed identically"

# 2. The disk fills during VTK output (in builds with VTK): the checkpoints of the whole run
#    fit, half of its VTK files do not.
"$lbdem" run "$case" "${small[@]}" --set output.checkpoint_interval_tc=1 --out "$work/vtk_whole" \
    --quiet || fail "the reference run with VTK failed"
if [ -d "$work/vtk_whole/vtk" ]; then
    frames=$(pages "$work/vtk_whole/vtk")
    others=$(pages "$work/vtk_whole" '^vtk/')
    checkpoint=$(pages "$work/vtk_whole/checkpoint.h5")
    mount_tmpfs $((others + checkpoint + frames / 2))
    "$lbdem" run "$case" "${small[@]}" --set output.checkpoint_interval_tc=1 --out "$disk/vtk" --force \
        --quiet 2> "$work/vtk.err"
    code=$?
    [ $code -eq 1 ] || fail "a full disk during VTK output: exit $code (expected 1): $(cat "$work/vtk.err")"
    expect_one_line "$work/vtk.err" 'cannot write .*vtk/[a-z]+(_[0-9]+\.vt[ui]|\.pvd): the disk is full'
    find "$disk/vtk" -name '*tmp*' | grep -q . && fail "temporary files left: $(find "$disk/vtk" -name '*tmp*')"
    for file in "$disk"/vtk/vtk/*.vt[ui]; do
        tail -c 32 "$file" | grep -q '</VTKFile>' || fail "$file is truncated"
    done
    echo "ok: full disk during VTK output: exit 1, one sentence, no partial frame"
else
    echo "note: this build writes no VTK files; the VTK part is left out"
fi

# 3. The pre-check: a submerged case, whose checkpoint (the lattice) outweighs its other
#    outputs, on a disk with room for one and a half checkpoints. Its first replacement could
#    not fit, so the run is refused before it starts (exit 2), where --force would run it.
wet=(--set grains.count=150 --set grains.packing=0.79 --set fluid.resolution=4 --set run.end_tc=0.1
     --set run.output_interval_tc=0.05 --set output.vtk=false)
"$lbdem" run "$case" "${wet[@]}" --until-tc 0.002 --out "$work/wet" --quiet || fail "the wet run failed"
checkpoint=$(pages "$work/wet/checkpoint.h5")
mount_tmpfs $((checkpoint * 3 / 2 / 4096 * 4096))
"$lbdem" run "$case" "${wet[@]}" --out "$disk/precheck" --quiet 2> "$work/precheck.err"
code=$?
[ $code -eq 2 ] || fail "a disk for 1.5 checkpoints: exit $code (expected 2): $(cat "$work/precheck.err")"
expect_one_line "$work/precheck.err" 'the run writes up to .* free in .*--force'
[ -e "$disk/precheck" ] && fail "the refused run created its folder"
echo "ok: the disk pre-check counts both checkpoints"

# 4. A read-only output folder: the same exit (2) and sentence from every command that writes.
mount_tmpfs $((64 << 20))
"$lbdem" run "$case" "${dry[@]}" --until-tc 0.05 --out "$disk/stopped" --quiet || fail "the stopped run failed"
mkdir "$disk/empty"
printf 'sweep = 1\nname = "s"\ncases = ["%s"]\n' "$case" > "$work/sweep.toml"
mount -o remount,ro "$disk" || { echo "skipped: cannot make the tmpfs read-only"; exit 77; }
for command in "run $case --out $disk/new" "run $case --out $disk/empty" "resume $disk/stopped" \
               "sweep $work/sweep.toml --out $disk/sweep" \
               "study $case --vary fluid.resolution=4,5 --out $disk/study"; do
    $lbdem $command --quiet 2> "$work/read_only.err"
    code=$?
    [ $code -eq 2 ] || fail "$command into a read-only folder: exit $code (expected 2): $(cat "$work/read_only.err")"
    expect_one_line "$work/read_only.err" "cannot write in $disk.*Read-only file system"
done
if "$lbdem" render --help > /dev/null 2>&1 && [ -d "$work/vtk_whole/vtk" ]; then
    "$lbdem" render "$work/vtk_whole" --png "$disk/frame.png" --quiet 2> "$work/read_only.err"
    code=$?
    [ $code -eq 2 ] || fail "render into a read-only folder: exit $code (expected 2): $(cat "$work/read_only.err")"
    expect_one_line "$work/read_only.err" "cannot write in $disk.*Read-only file system"
fi
umount "$disk"
echo "ok: a read-only output folder: exit 2 and one sentence in every command"
