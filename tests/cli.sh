#!/bin/sh
# cli.sh - the atrbvh command-line tool: exit status, messages, --help and
# --version everywhere, JSON output, NaN handling, save/info/compare.
# Run by `make check` with ATRBVH_BUILDDIR and ATRBVH_SRCDIR set.

# shellcheck source-path=SCRIPTDIR source=common.sh
. "$(dirname "$0")/common.sh"
DATA=$SRCDIR/data
setup cli

# out_has / err_has PATTERN (grep -E)
out_has() {
    grep -Eq -- "$1" "$T/out" || fail "stdout lacks /$1/: $(head -c 400 "$T/out")"
}
err_has() {
    grep -Eq -- "$1" "$T/err" || fail "stderr lacks /$1/: $(cat "$T/err")"
}

HAVE_PY=no
if command -v python3 >/dev/null 2>&1 && python3 -c 'import json' 2>/dev/null; then
    HAVE_PY=yes
fi

# json_check KEY... : stdout is one JSON object with every KEY (a.b for
# nested keys).
json_check() {
    if [ "$HAVE_PY" = yes ]; then
        python3 - "$T/out" "$@" <<'PY' || fail "JSON check failed: $(head -c 600 "$T/out")"
import json, math, sys
with open(sys.argv[1]) as f:
    text = f.read()
def bad_constant(name):
    raise ValueError("non-JSON constant " + name)
obj = json.loads(text, parse_constant=bad_constant)
assert isinstance(obj, dict), "not an object"
for key in sys.argv[2:]:
    o = obj
    for part in key.split("."):
        assert isinstance(o, dict) and part in o, "missing key " + key
        o = o[part]
PY
    else
        for key in "$@"; do
            last=${key##*.}
            grep -q "\"$last\":" "$T/out" || fail "JSON lacks key $key"
        done
    fi
}

# json_value KEY : prints the value of a top-level or dotted key.
json_value() {
    if [ "$HAVE_PY" = yes ]; then
        python3 -c 'import json,sys
o = json.load(open(sys.argv[1]))
for p in sys.argv[2].split("."): o = o[p]
print(json.dumps(o))' "$T/out" "$1"
    else
        last=${1##*.}
        sed -n "s/^ *\"$last\": *\([^,]*\),*$/\1/p" "$T/out" | head -n 1
    fi
}

BUILD_KEYS="triangles method treelet_size rounds backend threads sah nodes
leaves max_depth build_ms stages_ms scene invalid_skipped max_leaf_size ci ct
collapse"
STAGES="bounds morton sort hierarchy refit optimise collapse layout"

# ------------------------------------------------------ help and version
run 2 || true
run 0 --help && out_has '^Usage: atrbvh'
run 0 -h && out_has 'build SCENE'
run 0 --version && out_has '^atrbvh [0-9]+\.[0-9]+\.[0-9]+'
for cmd in build trace info compare; do
    run 0 $cmd --help && out_has "^Usage: atrbvh $cmd"
    run 0 $cmd --version && out_has '^atrbvh [0-9]'
    # --help wins over anything else on the line.
    run 0 $cmd --bogus --help && out_has "^Usage: atrbvh $cmd"
done

# `atrbvh help COMMAND` is that command's --help; every option a
# command's help shows is accepted (help and parser share one table).
for cmd in build trace info compare validate bench render; do
    run 0 help $cmd && out_has "^Usage: atrbvh $cmd"
    "$TOOL" $cmd --help >"$T/help1" 2>&1
    cmp -s "$T/out" "$T/help1" || fail "help $cmd differs from $cmd --help"
    for opt in $(sed -n 's/^ *\(-[a-z], \)\{0,1\}\(--[a-z-]*\).*/\2/p' "$T/help1"); do
        case $opt in --help | --version) continue ;; esac
        # (a last unknown option stops any run once $opt is read)
        "$TOOL" $cmd "$opt" zz-value --zz-not-an-option >"$T/o2" 2>"$T/e2"
        if grep -q "unknown option '$opt'" "$T/e2"; then
            fail "$cmd --help shows $opt, which $cmd refuses"
        fi
    done
done
run 2 help frobnicate && err_has 'unknown command'
# render has no JSON output, and its help does not claim one.
run 0 render --help
grep -q -- '--json' "$T/out" && fail "render --help advertises --json"
run 2 render builtin:sphere:100 -o "$T/r.png" --json && err_has "unknown option '--json'"
# validate saves nothing: -o is refused, not ignored, and not in its help.
run 0 validate --help
grep -Eq -- '--output|--backend' "$T/out" && fail "validate --help shows options it does not take"
run 2 validate builtin:sphere:100 -o "$T/v.bvh" && err_has "unknown option '-o'"
[ -e "$T/v.bvh" ] && fail "validate wrote $T/v.bvh"
# validate: 0 identical, 1 different, 2 trouble; --json says what the
# trouble was.
run 2 validate "$T/nothere.ply" && err_has 'nothere\.ply'
if run 2 validate "$T/nothere.ply" --json; then
    json_check scene identical error
    v=$(json_value identical)
    [ "$v" = null ] || fail "validate --json on a missing scene: identical is $v"
fi
# Without any OpenCL platform (an empty ICD folder): trouble, not a
# difference.
if OCL_ICD_VENDORS="$T/no-icds" "$TOOL" validate builtin:sphere:200 --json >"$T/out" 2>"$T/err"; then
    fail "validate without OpenCL exited 0"
else
    rc=$?
    checks=$((checks + 1))
    [ $rc = 2 ] || fail "validate without OpenCL exited $rc, expected 2: $(cat "$T/err")"
    json_check error
fi
if "$TOOL" validate builtin:sphere:200 --method lbvh >"$T/out" 2>"$T/err"; then
    checks=$((checks + 1))
    out_has 'identical at every stage'
    run 2 validate builtin:sphere:200 --device no-such-device-xyz &&
        err_has -- '--device: '
elif opencl_may_skip "$T/err"; then
    echo "cli.sh: validate on OpenCL skipped: $(cat "$T/err")"
else
    fail "validate on OpenCL: $(cat "$T/err")"
fi

# --version: the optional parts of this build and the licence
run 0 --version && {
    out_has '^Optional parts: OpenMP (yes|no), OpenCL (yes|no), Embree (yes|no), PNG (yes|no)$'
    out_has 'MIT License'
}

# ------------------------------------------------------------ usage: 2
run 2 frobnicate && err_has 'unknown command'
run 2 --frobnicate && err_has 'unknown option'
run 2 build && err_has 'no SCENE'
run 2 build "$DATA/cube.obj" --bogus && err_has "unknown option '--bogus'"
run 2 build "$DATA/cube.obj" --treelet abc && err_has "--treelet: 'abc'"
run 2 build "$DATA/cube.obj" --treelet -3
run 2 build "$DATA/cube.obj" --treelet 99999999999999999999
run 2 build "$DATA/cube.obj" --rounds 2x
run 2 build "$DATA/cube.obj" --threads 1.5
run 2 build "$DATA/cube.obj" --ci abc
run 2 build "$DATA/cube.obj" --ct ''
run 2 build "$DATA/cube.obj" --max-leaf
run 2 build "$DATA/cube.obj" --method bogus && err_has 'lbvh, trbvh or atrbvh'
run 2 build "$DATA/cube.obj" "$DATA/tetra.ply" && err_has 'more than one'
run 2 trace "$DATA/cube.obj" --width 0
run 2 trace "$DATA/cube.obj" --height abc
run 2 trace "$DATA/cube.obj" --spp 100000
run 2 info && err_has 'no FILE'
run 2 info a b
run 2 compare onlyone
run 2 compare a b --json

# ----------------------------------------------------- bad input: 1
run 1 build "$T/missing.ply" && err_has 'missing\.ply'
run 1 build "$T/scene.stl" && err_has 'unknown scene type'
run 1 build builtin:teapot && err_has 'teapot'
run 1 build builtin:sphere:0 && err_has 'builtin:sphere:0'
run 1 build builtin:sphere:50000001
run 1 build "$DATA/empty.obj" --method lbvh && err_has 'empty\.obj: .*no triangles'
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 oops 0\n0 1 0\n' >"$T/bad.ply"
run 1 build "$T/bad.ply" && err_has 'bad\.ply: line 9: .*oops'
# An endless stream of zeros as an OBJ file: refused at its first NUL byte
# (before, the reader took it all into memory).  The tool runs with a
# bounded address space but under ASan (which reserves more), so that
# such a reader fails instead of filling the machine.
if [ -c /dev/zero ]; then
    ln -s /dev/zero "$T/zero.obj"
    checks=$((checks + 1))
    (
        [ -n "${ATRBVH_TEST_SANITIZER:-}" ] || ulimit -v 4000000
        exec timeout 60 "$TOOL" build "$T/zero.obj"
    ) >"$T/out" 2>"$T/err"
    rc=$?
    [ "$rc" = 1 ] && grep -q 'zero\.obj: line 1: NUL byte' "$T/err" ||
        fail "build of /dev/zero as OBJ: exit $rc: $(cat "$T/err")"
    # as a BVH file: no size to check the header against, said so (not
    # "truncated: 0 bytes")
    run 1 info /dev/zero && err_has '/dev/zero: .*not a regular file'
fi
# Out-of-range option values are usage errors (2) naming the option, found
# before the scene is read and never blamed on it (the scene here does not
# even exist).
for cmd in build trace render validate; do
    out=
    [ $cmd = render ] && out="-o $T/never.png"
    for bad in "--threads -1" "--threads 100000" "--threads 2147483647" \
        "--rounds -1" "--ci -1" "--ct nan" "--max-leaf -1"; do
        opt=${bad%% *}
        run 2 $cmd "$T/nothere.ply" $out $bad &&
            err_has "^atrbvh: $cmd: $opt: " &&
            { ! grep -q 'nothere' "$T/err" || fail "$cmd $bad: blamed on the scene: $(cat "$T/err")"; }
    done
    # the library's own limits, asked before loading
    run 2 $cmd "$T/nothere.ply" $out --method trbvh --treelet 100 &&
        err_has "^atrbvh: $cmd: --treelet: .*trbvh"
    run 2 $cmd "$T/nothere.ply" $out --max-leaf 4 --no-collapse &&
        err_has "^atrbvh: $cmd: --max-leaf: "
    # auto is ATRBVH's alone, said so (not as the size it stands for)
    run 2 $cmd "$T/nothere.ply" $out --method trbvh --treelet auto &&
        err_has "^atrbvh: $cmd: --treelet: .*auto.* atrbvh only" &&
        { ! grep -q '4294967295' "$T/err" || fail "$cmd: auto given as a number: $(cat "$T/err")"; }
    # LBVH takes no treelet size or rounds, given in either order; a
    # preset's own are not the user's, and a later preset overrides
    run 2 $cmd "$T/nothere.ply" $out --method lbvh --treelet 9 &&
        err_has "^atrbvh: $cmd: --treelet: lbvh takes no"
    run 2 $cmd "$T/nothere.ply" $out --rounds 3 --method lbvh &&
        err_has "^atrbvh: $cmd: --rounds: lbvh takes no"
    run 2 $cmd "$T/nothere.ply" $out --quality fast --treelet 9 &&
        err_has "^atrbvh: $cmd: --treelet: lbvh takes no"
done
run 0 build builtin:sphere:50 --quality balanced --method lbvh
run 0 build builtin:sphere:50 --treelet 9 --rounds 1 --quality fast
# --device only with --backend opencl (validate always uses OpenCL)
for cmd in build trace render; do
    out=
    [ $cmd = render ] && out="-o $T/never.png"
    run 2 $cmd builtin:sphere:100 $out --device 0:0 && err_has -- '--device needs --backend opencl'
done

# NaN: an error naming the primitive (triangle 1), unless skipped.
run 1 build "$DATA/nan.obj" --method lbvh && err_has '^atrbvh: .*nan\.obj: .*[^0-9]1([^0-9]|$)'
if run 0 build "$DATA/nan.obj" --method lbvh --skip-invalid --json; then
    json_check $BUILD_KEYS
    v=$(json_value invalid_skipped)
    [ "$v" = 1 ] || fail "invalid_skipped is '$v', expected 1"
    v=$(json_value triangles)
    [ "$v" = 3 ] || fail "triangles is '$v', expected 3"
fi

# Triangle splitting: off by default (no references key), --split B adds
# at most B * triangles references, saved as format version 2 and shown by
# info; out of range is a usage error naming --split.
run 2 build "$T/nothere.ply" --split 4.5 && err_has '^atrbvh: build: --split: '
run 2 build "$T/nothere.ply" --split -1 && err_has '^atrbvh: build: --split: '
if run 0 build builtin:sphere:3000 --json; then
    grep -q '"references"' "$T/out" && fail "references reported without --split"
fi
if run 0 build builtin:sphere:3000 --split 0.3 --json -o "$T/split.bvh"; then
    t=$(json_value triangles)
    r=$(json_value references)
    p=$(json_value primitives)
    [ "$p" = "$t" ] || fail "--split: primitives '$p', triangles '$t'"
    [ "$(json_value split_rule)" = '"sah"' ] ||
        fail "--split: split_rule '$(json_value split_rule)', expected \"sah\""
    [ -n "$r" ] && [ "$r" -gt "$t" ] && [ $((r * 10)) -le $((t * 13)) ] ||
        fail "--split 0.3: references '$r' for $t triangles"
    ver=$(od -An -tu4 -j8 -N4 "$T/split.bvh" | tr -d ' ')
    [ "$ver" = 2 ] || fail "--split: file version '$ver', expected 2"
    run 0 info "$T/split.bvh" && out_has "^references +$r "
fi
run 2 build "$T/nothere.ply" --split 0.3 --split-rule bogus &&
    err_has '^atrbvh: build: --split-rule: '
if run 0 build builtin:sphere:3000 --split 0.3 --split-rule tree --json; then
    r=$(json_value references) t=$(json_value triangles)
    [ "$r" -ge "$t" ] && [ $((r * 10)) -le $((t * 13)) ] ||
        fail "--split-rule tree: references '$r' for $t triangles"
    [ "$(json_value split_rule)" = '"tree"' ] ||
        fail "--split-rule tree: split_rule '$(json_value split_rule)'"
fi
if run 0 build builtin:sphere:3000 --split 0.3 --split-rule priority --json; then
    [ "$(json_value references)" -gt "$(json_value triangles)" ] ||
        fail "--split-rule priority: nothing split"
    [ "$(json_value split_rule)" = '"priority"' ] ||
        fail "--split-rule priority: split_rule '$(json_value split_rule)'"
fi
if run 0 build builtin:sphere:3000 --split 0.3 --split-rule sah --json; then
    r=$(json_value references) t=$(json_value triangles)
    [ "$r" -gt "$t" ] || fail "--split-rule sah: nothing split"
    [ "$r" -le $((t + t * 3 / 10)) ] ||
        fail "--split-rule sah: references '$r' for $t triangles"
    [ "$(json_value split_rule)" = '"sah"' ] ||
        fail "--split-rule sah: split_rule '$(json_value split_rule)'"
fi

# ------------------------------------------------------------- build
run 0 build "$DATA/cube.obj" --method lbvh && {
    out_has '^triangles +12'
    out_has '^SAH'
    out_has '^max depth'
    out_has '^build +[0-9.]+ ms'
}
for scene in "$DATA/cube.obj" "$DATA/tetra.ply" "$DATA/quad_be.ply" \
    builtin:sphere:500 builtin:terrain:500 builtin:city:500; do
    if run 0 build "$scene" --method lbvh --json; then
        json_check $BUILD_KEYS
        for st in $STAGES; do json_check "stages_ms.$st"; done
        v=$(json_value backend)
        [ "$v" = '"cpu"' ] || fail "backend is $v"
    fi
done
# Strings are escaped, and bytes that are not UTF-8 replaced: the output
# stays valid JSON whatever the file is called.
odd="$T/$(printf 'q"b\\s\tt\377')x.obj"
if cp "$DATA/cube.obj" "$odd" 2>/dev/null; then
    run 0 build "$odd" --method lbvh --json && json_check scene triangles
fi
if run 0 build "$DATA/cube.obj" --method lbvh --no-collapse --json; then
    v=$(json_value leaves)
    [ "$v" = 12 ] || fail "--no-collapse: $v leaves, expected 12"
    v=$(json_value collapse)
    [ "$v" = false ] || fail "--no-collapse: collapse is $v"
fi
if run 0 build builtin:city:2000 --method lbvh --max-leaf 2 --ci 2.5 --ct=0.5 --threads 1 --json; then
    v=$(json_value max_leaf_primitives)
    [ "$v" -le 2 ] 2>/dev/null || fail "--max-leaf 2: largest leaf $v"
    v=$(json_value ci)
    [ "$v" = 2.5 ] || fail "ci is $v"
    v=$(json_value threads)
    [ "$v" = 1 ] || fail "threads is $v"
fi
# The default method, as the README's main job runs it.
run 0 build builtin:sphere:2000 && out_has '^method +atrbvh'

# ------------------------------------------ save, info, compare
if run 0 build "$DATA/tetra.ply" --method lbvh --output "$T/a.bvh" &&
    run 0 build "$DATA/tetra.ply" --method lbvh --threads 1 -o "$T/b.bvh" &&
    run 0 build builtin:sphere:300 --method lbvh --output="$T/c.bvh"; then
    run 0 compare "$T/a.bvh" "$T/b.bvh" && out_has 'identical'
    run 1 compare "$T/a.bvh" "$T/c.bvh" && err_has 'differ'
    run 0 info "$T/a.bvh" && out_has '^nodes'
    run 0 info --json "$T/c.bvh" &&
        json_check file primitives method nodes leaves max_depth sah
    run 1 info "$DATA/cube.obj" && err_has 'cube\.obj'
    # As cmp: 0 same, 1 different, 2 trouble (a file that cannot be read).
    run 2 compare "$T/a.bvh" "$T/nothere.bvh" && err_has 'nothere\.bvh'
    run 2 compare "$DATA/cube.obj" "$T/a.bvh" && err_has 'cube\.obj'
fi
run 1 build "$DATA/cube.obj" --method lbvh --output "$T/no/such/dir/x.bvh" &&
    err_has 'x\.bvh'

# ------------------------------------------------------------- trace
if run 0 trace builtin:sphere:2000 --method lbvh --width 32 --height 24 --spp 2 --json; then
    json_check $BUILD_KEYS rays.primary.count rays.primary.hits \
        rays.primary.mrays rays.ao.count rays.ao.hits rays.ao.mrays \
        rays.diffuse.count rays.diffuse.hits rays.diffuse.mrays
    v=$(json_value rays.primary.count)
    [ "$v" = 768 ] || fail "primary count $v, expected 768"
    hits=$(json_value rays.primary.hits)
    [ "$hits" -gt 0 ] 2>/dev/null || fail "no primary hits ($hits)"
    v=$(json_value rays.ao.count)
    [ "$v" = $((hits * 2)) ] || fail "ao count $v, expected $((hits * 2))"
    v=$(json_value rays.diffuse.count)
    [ "$v" = $((hits * 2)) ] || fail "diffuse count $v, expected $((hits * 2))"
    # A convex sphere cannot occlude itself.
    v=$(json_value rays.ao.hits)
    [ "$v" = 0 ] || fail "sphere: $v occluded AO rays"
fi
# A triangle spanning 3e38 (near the end of the float range): the default
# camera stays where floats reach and its rays hit (before, the eye was
# so far out that no hit's distance was a float: 0 hits, no warning).
printf 'v 0 0 0\nv 3e38 0 0\nv 0 3e38 0\nf 1 2 3\n' >"$T/huge.obj"
if run 0 trace "$T/huge.obj" --width 32 --height 24 --spp 1 --json; then
    hits=$(json_value rays.primary.hits)
    [ "$hits" -gt 0 ] 2>/dev/null || fail "a 3e38 triangle: no primary hits ($hits)"
fi
# Rays are a function of pixel and sample only: the same hits on any
# number of threads.
hits1= hits2=
if run 0 trace builtin:city:3000 --method lbvh --width 24 --height 16 --threads 1 --json; then
    hits1="$(json_value rays.primary.hits) $(json_value rays.ao.hits) $(json_value rays.diffuse.hits)"
fi
if run 0 trace builtin:city:3000 --method lbvh --width 24 --height 16 --threads 3 --json; then
    hits2="$(json_value rays.primary.hits) $(json_value rays.ao.hits) $(json_value rays.diffuse.hits)"
fi
[ "$hits1" = "$hits2" ] || fail "hit counts differ with 1 and 3 threads: $hits1 / $hits2"
# On the OpenCL device: the same hits (the kernels run the CPU's per-ray
# code), and the kernel times.  Skipped without an OpenCL device.
if "$TOOL" trace builtin:city:3000 --method lbvh --width 24 --height 16 \
    --backend opencl --json >"$T/out" 2>"$T/err"; then
    checks=$((checks + 1))
    json_check rays.primary.kernel_ms rays.ao.kernel_mrays \
        rays.diffuse.kernel_mrays trace_device
    hits3="$(json_value rays.primary.hits) $(json_value rays.ao.hits) $(json_value rays.diffuse.hits)"
    [ "$hits1" = "$hits3" ] || fail "hit counts differ on cpu and opencl: $hits1 / $hits3"
elif opencl_may_skip "$T/err"; then
    echo "cli.sh: trace --backend opencl skipped: $(cat "$T/err")"
else
    fail "trace --backend opencl: $(cat "$T/err")"
fi
run 0 trace builtin:city:3000 --method lbvh --width 40 --height 30 &&
    out_has '^ +primary +1200 ' && out_has '^ +ao ' && out_has '^ +diffuse '

# Progress: on a terminal (a pty from script(1)) a long build shows it,
# --quiet silences it; when stderr is not a terminal there is none.
run 0 build builtin:city:300000 --quality high --threads 2 &&
    [ ! -s "$T/err" ] || fail "progress written to a stderr that is no terminal"
if command -v script >/dev/null 2>&1; then
    checks=$((checks + 1))
    ATRBVH_PROGRESS_AFTER_MS=0 script -qc \
        "'$TOOL' build builtin:city:300000 --quality high --threads 1" \
        /dev/null >"$T/pty" 2>&1 </dev/null
    grep -q "atrbvh: building: [a-z]* *[0-9]*%  [0-9.]* s" "$T/pty" ||
        fail "no progress line on a terminal: $(tr '\r' '\n' <"$T/pty" | head -3)"
    checks=$((checks + 1))
    ATRBVH_PROGRESS_AFTER_MS=0 script -qc \
        "'$TOOL' build builtin:city:300000 --quality high --threads 1 --quiet" \
        /dev/null >"$T/pty" 2>&1 </dev/null
    grep -q "atrbvh: building" "$T/pty" && fail "--quiet still shows progress"
else
    echo "cli.sh: script(1) missing, progress on a terminal not checked"
fi

finish
