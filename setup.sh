#!/bin/sh
# setup.sh - install what building atrbvh needs on Debian, then configure
# and build it in _build/.  Safe to run again.  Used by the README and by
# .ci/run.
#
#   sh setup.sh                  the build's packages (.ci/packages.d/10-build.txt:
#                                compiler with OpenMP, autotools, pkg-config,
#                                the OpenCL headers and ICD loader), then
#                                autoreconf, configure, make in _build/
#   sh setup.sh --all            every package the test suite uses (all of
#                                .ci/packages.d/*.txt), then the same build
#   sh setup.sh --packages LIST...
#                                only install the lists named (a name N
#                                stands for .ci/packages.d/*-N.txt), no build:
#                                what each stage of tests/suite.d/ runs
#                                first, so that the test command installs
#                                the rest itself
#
# Packages are installed with apt-get (through sudo when not root), only
# when missing, without recommends and without questions (no stdin needed).
set -eu
cd "$(dirname "$0")"

# install NAME... : the packages of .ci/packages.d/*-NAME.txt that are missing
install_lists() {
    files=""
    for n in "$@"; do
        f=$(ls .ci/packages.d/*-"$n".txt 2>/dev/null | head -n 1)
        [ -n "$f" ] || { echo "setup.sh: no package list .ci/packages.d/*-$n.txt" >&2; exit 2; }
        files="$files $f"
    done
    missing=""
    # shellcheck disable=SC2086
    for p in $(sed 's/#.*//' $files | sort -u); do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" ||
            missing="$missing $p"
    done
    [ -n "$missing" ] || return 0
    installed=yes
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    echo "setup.sh: installing$missing"
    # Try with the package lists there are; update them only when that
    # fails (a fresh machine has none), so that each stage does not pay for
    # an update.
    # shellcheck disable=SC2086
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq \
        --no-install-recommends $missing </dev/null >/dev/null 2>&1 || {
        $sudo apt-get update -qq </dev/null
        DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq \
            --no-install-recommends $missing </dev/null
    }
}

all_lists() {
    for f in .ci/packages.d/*-*.txt; do
        n=${f##*/}; n=${n#*-}; echo "${n%.txt}"
    done
}

installed=no
case "${1:-}" in
    --packages)
        shift
        install_lists "$@"
        exit 0
        ;;
    --all)
        # shellcheck disable=SC2046
        install_lists $(all_lists)
        ;;
    "")
        install_lists build
        ;;
    *)
        echo "usage: sh setup.sh [--all | --packages LIST...]" >&2
        exit 2
        ;;
esac

mkdir -p m4
autoreconf -fi
mkdir -p _build
cd _build
if [ ! -f Makefile ]; then
    ../configure
elif [ "$installed" = yes ]; then
    # configured before these packages were there: look again (same
    # arguments), so that the build finds them
    ./config.status --recheck && ./config.status
fi
make -j"$(nproc)"
