#!/bin/sh
# outputs.sh - nothing the atrbvh tool writes is ever lost or half written:
#  - a failing write (full file system: a 64 KiB tmpfs when root, a file
#    size limit for any user) leaves the existing output byte for byte and
#    no temporary file, with one error line naming the file (bench's --csv
#    and --builds both, though only one failed); SIGXFSZ ending the
#    process mid-write leaves no temporary file either;
#  - devices (a private mknod copy of /dev/full when root, /dev/full through
#    a symbolic link) and symbolic links to /dev/stdout are written in place
#    and never removed;
#  - an output naming the input scene (itself, a link, a hard link) is
#    refused before the build, the scene intact;
#  - an unwritable output (missing directory, a directory) is reported
#    before the scene is even read;
#  - render leaves no truncated PNG;
#  - --plot: gnuplot writes into a folder of its own, its pictures put in
#    place only when it succeeded; the folder's other files (a user's
#    NAME.part included) are left alone, and nothing of gnuplot's is left
#    behind (a fake gnuplot first in PATH, succeeding and failing);
#  - --threads above ATRBVH_MAX_THREADS is a usage error.
# Run by `make check` with ATRBVH_BUILDDIR and ATRBVH_SRCDIR set.

# shellcheck source-path=SCRIPTDIR source=common.sh
. "$(dirname "$0")/common.sh"
MNT=
cleanup() {
    [ -n "$MNT" ] && umount "$MNT" 2>/dev/null
    rm -rf "$T"
}
setup outputs

err_has() {
    grep -Fq -- "$1" "$T/err" || fail "stderr lacks '$1': $(cat "$T/err")"
}

# only NAMES... : the directory $D holds exactly these names (no temporary
# file left behind).
only() {
    have=$(cd "$D" && ls -A | sort | tr '\n' ' ')
    want=$(for n in "$@"; do echo "$n"; done | sort | tr '\n' ' ')
    [ "$have" = "$want" ] || fail "$D holds '$have', expected '$want'"
}

SCENE=builtin:sphere:20000 # a BVH of about 1.3 MB
SMALL=builtin:sphere:200

# A small PLY scene, as a file the tool could overwrite.
cat >"$T/tri.ply" <<'EOF'
ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
1 1 0
3 0 1 2
3 1 3 2
EOF
cp "$T/tri.ply" "$T/tri.orig"

HAVE_PNG=yes
"$TOOL" render "$T/tri.ply" -o "$T/probe.png" --width 8 --height 8 \
    >/dev/null 2>"$T/err" || HAVE_PNG=no
rm -f "$T/probe.png"

# ------------------------------------------- the output names the input
D=$T
for cmd in build trace; do
    run 1 $cmd "$T/tri.ply" -o "$T/tri.ply" && err_has "tri.ply"
    cmp -s "$T/tri.ply" "$T/tri.orig" || fail "$cmd -o SCENE changed the scene"
done
ln -s tri.ply "$T/link.ply"
ln "$T/tri.ply" "$T/hard.ply"
run 1 build "$T/tri.ply" -o "$T/link.ply"
run 1 build "$T/link.ply" -o "$T/hard.ply"
cmp -s "$T/tri.ply" "$T/tri.orig" || fail "-o LINK-TO-SCENE changed the scene"
if [ "$HAVE_PNG" = yes ]; then
    run 1 render "$T/tri.ply" -o "$T/tri.ply"
    cmp -s "$T/tri.ply" "$T/tri.orig" || fail "render -o SCENE changed the scene"
fi
rm -f "$T/link.ply" "$T/hard.ply"

# ------------------------------ unwritable outputs: before reading SCENE
# (the scene does not exist: the error must be about the output)
run 1 build "$T/no-such-scene.ply" -o "$T/no/such/dir/x.bvh" &&
    err_has "$T/no/such/dir/x.bvh"
run 1 build "$T/no-such-scene.ply" -o "$T" && err_has "$T"
run 1 trace "$T/no-such-scene.ply" -o "$T/no/such/dir/x.bvh" &&
    err_has "$T/no/such/dir/x.bvh"
if [ "$HAVE_PNG" = yes ]; then
    run 1 render "$T/no-such-scene.ply" -o "$T/no/such/dir/x.png" &&
        err_has "$T/no/such/dir/x.png"
fi

# --------------------------------- replacing: atomic, mode and link kept
D=$T/rep
mkdir "$D"
run 0 build $SMALL -o "$D/small.bvh"
run 0 build $SCENE -o "$D/big.bvh"
cp "$D/small.bvh" "$D/t.bvh"
chmod 640 "$D/t.bvh"
ln -s t.bvh "$D/l.bvh"
run 0 build $SCENE -o "$D/l.bvh"
[ -L "$D/l.bvh" ] || fail "the symbolic link output was replaced by a file"
cmp -s "$D/t.bvh" "$D/big.bvh" || fail "the link's target was not rewritten"
case $(ls -l "$D/t.bvh") in
-rw-r-----*) ;;
*) fail "the replaced file lost its mode: $(ls -l "$D/t.bvh")" ;;
esac
only small.bvh big.bvh t.bvh l.bvh

# -------------------------- a full file system: the old output survives
# A file size limit works for any user (SIGXFSZ ignored: writes fail with
# EFBIG); `ulimit -f` counts 512- or 1024-byte blocks: 64 is at most 64 KiB.
cp "$D/small.bvh" "$D/t.bvh"
checks=$((checks + 1))
(
    trap '' XFSZ
    ulimit -f 64 2>/dev/null || exit 77
    exec "$TOOL" build $SCENE -o "$D/t.bvh"
) >"$T/out" 2>"$T/err"
rc=$?
if [ "$rc" -eq 77 ]; then
    echo "outputs.sh: ulimit -f not available: file size limit skipped"
else
    [ "$rc" -eq 1 ] || fail "build past a file size limit exited $rc: $(cat "$T/err")"
    [ "$(wc -l <"$T/err")" -eq 1 ] || fail "not one error line: $(cat "$T/err")"
    err_has "$D/t.bvh"
    cmp -s "$D/t.bvh" "$D/small.bvh" || fail "a failed write lost the existing output"
    only small.bvh big.bvh t.bvh l.bvh
    # bench --csv and --builds: both or neither (the builds log, some
    # 15 KB, past the limit; the CSV, under 2 KB, within it)
    echo old >"$D/a.csv"
    echo old >"$D/b.csv"
    checks=$((checks + 1))
    (
        trap '' XFSZ
        ulimit -f 8
        exec "$TOOL" bench $SMALL --no-rays --repeat 60 --configs lbvh \
            --csv "$D/a.csv" --builds "$D/b.csv"
    ) >"$T/out" 2>"$T/err"
    rc=$?
    [ "$rc" -eq 1 ] || fail "bench past a file size limit exited $rc: $(cat "$T/err")"
    [ "$(wc -l <"$T/err")" -eq 1 ] || fail "bench: not one error line: $(cat "$T/err")"
    err_has "$D/b.csv"
    [ "$(cat "$D/a.csv")$(cat "$D/b.csv")" = oldold ] ||
        fail "bench: --csv or --builds replaced though the other failed"
    only small.bvh big.bvh t.bvh l.bvh a.csv b.csv
    rm -f "$D/a.csv" "$D/b.csv"
    if [ "$HAVE_PNG" = yes ]; then
        echo "not a png" >"$D/old.png"
        checks=$((checks + 1))
        (
            trap '' XFSZ
            ulimit -f 2
            exec "$TOOL" render $SCENE -o "$D/old.png" --width 1024 --height 1024
        ) >"$T/out" 2>"$T/err"
        rc=$?
        [ "$rc" -eq 1 ] || fail "render past a file size limit exited $rc: $(cat "$T/err")"
        [ "$(wc -l <"$T/err")" -eq 1 ] || fail "render: not one error line: $(cat "$T/err")"
        err_has "$D/old.png"
        [ "$(cat "$D/old.png")" = "not a png" ] || fail "render: the old PNG was lost"
        only small.bvh big.bvh t.bvh l.bvh old.png
        rm -f "$D/old.png"
    fi
fi

# The same limit without ignoring SIGXFSZ: the signal ends the process in
# the middle of the write; the temporary file goes with it.
D=$T/rep
checks=$((checks + 1))
(
    ulimit -f 64 2>/dev/null || exit 77
    "$TOOL" build $SCENE -o "$D/t.bvh"
    exit $? # (not the last command: this subshell reports the signal)
) >"$T/out" 2>"$T/err"
rc=$?
if [ "$rc" -ne 77 ]; then
    [ "$rc" -ne 0 ] || fail "build past a file size limit succeeded"
    cmp -s "$D/t.bvh" "$D/small.bvh" || fail "SIGXFSZ lost the existing output"
    only small.bvh big.bvh t.bvh l.bvh
fi

# A real full file system (root only: a 64 KiB tmpfs).
D=$T/full
mkdir "$D"
if mount -t tmpfs -o size=64k tmpfs "$D" 2>/dev/null; then
    MNT=$D
    "$TOOL" build $SMALL -o "$D/t.bvh" >/dev/null 2>&1
    cp "$D/t.bvh" "$T/t.copy"
    run 1 build $SCENE -o "$D/t.bvh" && err_has "$D/t.bvh"
    cmp -s "$D/t.bvh" "$T/t.copy" || fail "a full disk lost the existing output"
    only t.bvh
    # now truly full: even a small file cannot be written
    dd if=/dev/zero of="$D/fill" bs=1024 2>/dev/null
    run 1 build $SMALL -o "$D/t.bvh" && err_has "$D/t.bvh"
    cmp -s "$D/t.bvh" "$T/t.copy" || fail "a full disk lost the existing output"
    if [ "$HAVE_PNG" = yes ]; then
        run 1 render "$T/tri.ply" -o "$D/x.png" --width 64 --height 64 &&
            err_has "$D/x.png"
    fi
    only t.bvh fill
    umount "$D" && MNT=
else
    echo "outputs.sh: cannot mount a tmpfs (not root): full file system skipped"
fi

# ------------------------- devices and /dev/stdout: in place, never removed
D=$T/dev
mkdir "$D"
if [ -c /dev/full ]; then
    ln -s /dev/full "$D/full-link"
    run 1 build $SMALL -o "$D/full-link" && err_has "$D/full-link"
    [ -L "$D/full-link" ] || fail "the link to /dev/full was removed"
    [ -c /dev/full ] || fail "/dev/full is gone"
    if [ "$HAVE_PNG" = yes ]; then
        run 1 render "$T/tri.ply" -o "$D/full-link" --width 8 --height 8 &&
            err_has "$D/full-link"
        [ -L "$D/full-link" ] || fail "render removed the link to /dev/full"
    fi
    # (1, 7 is /dev/full on Linux only)
    if [ "$(uname -s)" = Linux ] && mknod "$D/full-node" c 1 7 2>/dev/null; then
        run 1 build $SMALL -o "$D/full-node" && err_has "$D/full-node"
        [ -c "$D/full-node" ] || fail "the device node was removed or replaced"
        run 1 trace $SMALL -o "$D/full-node" --width 4 --height 4
        [ -c "$D/full-node" ] || fail "trace removed or replaced the device node"
    else
        echo "outputs.sh: mknod not permitted: private device node skipped"
    fi
else
    echo "outputs.sh: no /dev/full: device checks skipped"
fi
if [ -c /dev/full ] && [ -e /dev/stdout ]; then
    ln -s /dev/stdout "$D/stdout-link"
    run 0 build $SMALL -o "$D/small.bvh"
    checks=$((checks + 1))
    "$TOOL" build $SMALL -o "$D/stdout-link" >"$D/stdout.out" 2>"$T/err" ||
        fail "build -o LINK-TO-/dev/stdout failed: $(cat "$T/err")"
    [ -L "$D/stdout-link" ] || fail "the link to /dev/stdout was replaced"
    n=$(wc -c <"$D/small.bvh")
    head -c "$n" "$D/stdout.out" | cmp -s - "$D/small.bvh" ||
        fail "-o /dev/stdout: the BVH is not at the start of stdout"
    checks=$((checks + 1))
    "$TOOL" build $SMALL -o "$D/stdout-link" >/dev/full 2>"$T/err" &&
        fail "build -o /dev/stdout with stdout full succeeded"
    [ -L "$D/stdout-link" ] || fail "a failed write removed the link to /dev/stdout"
    [ -c /dev/full ] || fail "/dev/full is gone"
else
    echo "outputs.sh: no /dev/stdout: its checks skipped"
fi
# Standard output that cannot be written: a failure (1) for a command that
# makes something, trouble (2) for those that compare (1 is "different");
# one error line either way.  (A "differ" goes to standard error: nothing
# is lost then.)
if [ -c /dev/full ]; then
    for c in "info $D/small.bvh:1" "compare $D/small.bvh $D/small.bvh:2" \
             "validate $SMALL:2"; do
        checks=$((checks + 1))
        # shellcheck disable=SC2086 # (the words of the command)
        "$TOOL" ${c%:*} >/dev/full 2>"$T/err"
        got=$?
        # (validate needs an OpenCL device: trouble of another kind
        # without one, where the suite allows that)
        if [ "${c%% *}" = validate ] && opencl_may_skip "$T/err"; then
            echo "outputs.sh: validate >/dev/full skipped: $(cat "$T/err")"
            continue
        fi
        [ "$got" = "${c##*:}" ] && [ "$(wc -l <"$T/err")" = 1 ] &&
            grep -q 'writing standard output' "$T/err" ||
            fail "${c%:*} >/dev/full: exit $got, want ${c##*:}: $(cat "$T/err")"
    done
fi

# --------------------------------- --plot: gnuplot in a folder of its own
# The fake gnuplot: `gnuplot -e "outdir = 'SUB/'" SCRIPT`, run in the plot
# folder; writes the word of fake_gnuplot WORD STATUS into each of animate
# --plot's pictures in SUB, says so on stderr and exits with STATUS (for
# the word "hang", first says it is ready and sleeps).
mkdir "$T/fake"
cat >"$T/fake/gnuplot" <<'EOF'
#!/bin/sh
here=$(dirname "$0")
sub=$(printf '%s' "$2" | sed "s/^outdir = '\(.*\)'\$/\1/")
for p in sah.png sah.svg ms.png ms.svg; do cat "$here/word" >"$sub$p"; done
echo "fake gnuplot: $(cat "$here/word")" >&2
if [ "$(cat "$here/word")" = hang ]; then
    echo $$ >"$here/pid"
    exec sleep 60
fi
exit "$(cat "$here/status")"
EOF
chmod +x "$T/fake/gnuplot"
fake_gnuplot() {
    printf '%s\n' "$1" >"$T/fake/word"
    printf '%s\n' "$2" >"$T/fake/status"
}
D=$T/plot
mkdir "$D"
echo mine >"$D/sah.png.part"
echo mine >"$D/keep.txt"
echo "old picture" >"$D/sah.png"
OLDPATH=$PATH
PATH=$T/fake:$PATH
fake_gnuplot broken 1
if run 1 animate builtin:wave:500 --frames 2 --plot "$D"; then
    err_has "gnuplot failed (see $D/gnuplot.log)"
    [ "$(cat "$D/sah.png")" = "old picture" ] ||
        fail "a failed gnuplot replaced sah.png"
    grep -q "fake gnuplot: broken" "$D/gnuplot.log" ||
        fail "gnuplot.log: $(cat "$D/gnuplot.log")"
fi
only animate.dat animate.gp gnuplot.log keep.txt sah.png sah.png.part
fake_gnuplot drawn 0
if run 0 animate builtin:wave:500 --frames 2 --plot "$D"; then
    for p in sah.png sah.svg ms.png ms.svg; do
        [ "$(cat "$D/$p")" = drawn ] || fail "--plot: $p is not gnuplot's"
    done
fi
only animate.dat animate.gp gnuplot.log keep.txt sah.png sah.png.part \
    sah.svg ms.png ms.svg
# Killed while gnuplot runs: gnuplot is ended first (it could go on
# writing after the cleanup), then its folder and what it wrote there go.
fake_gnuplot hang 0
"$TOOL" animate builtin:wave:500 --frames 2 --plot "$D" >/dev/null 2>&1 &
tool=$!
i=0
while [ ! -s "$T/fake/pid" ] && [ $i -lt 300 ]; do
    sleep 0.1
    i=$((i + 1))
done
kill -TERM $tool
wait $tool
killed=$?
if [ -s "$T/fake/pid" ] && kill -0 "$(cat "$T/fake/pid")" 2>/dev/null; then
    fail "gnuplot outlived the tool killed by SIGTERM"
    kill "$(cat "$T/fake/pid")" 2>/dev/null
fi
[ -s "$T/fake/pid" ] || fail "the fake gnuplot never started"
[ $killed -eq 143 ] || fail "animate --plot killed by SIGTERM exited $killed"
only animate.dat animate.gp gnuplot.log keep.txt sah.png sah.png.part \
    sah.svg ms.png ms.svg
[ "$(cat "$D/sah.png")" = drawn ] || fail "a killed gnuplot replaced sah.png"
checks=$((checks + 1))
PATH=$OLDPATH
[ "$(cat "$D/sah.png.part")$(cat "$D/keep.txt")" = minemine ] ||
    fail "--plot changed the folder's other files"

# ------------------------------------------------------------- --threads
run 2 build $SMALL --threads 100000 && err_has "--threads"
run 2 build $SMALL --threads 2147483647 && err_has "--threads"
run 0 build $SMALL --threads 2

finish
