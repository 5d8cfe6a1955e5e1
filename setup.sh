#!/bin/sh
# setup.sh - install what atrbvh needs on Debian (the lists in
# .ci/packages.d/*.txt, one package per line), then configure and build it
# in _build/.  Safe to run again.  Used by the README and by .ci/run.
set -eu
cd "$(dirname "$0")"

missing=""
for p in $(cat .ci/packages.d/*.txt | sed 's/#.*//'); do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" ||
        missing="$missing $p"
done
if [ -n "$missing" ]; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    echo "setup.sh: installing$missing"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq \
        --no-install-recommends $missing </dev/null
fi

autoreconf -fi
mkdir -p _build
cd _build
[ -f Makefile ] || ../configure
make -j"$(nproc)"
