#!/bin/sh
# libFuzzer harnesses (tests/fuzz/): each for $FUZZ_SECONDS (30) seconds
# from its seed corpus, under ASan and UBSan.
# Contract: print '=== stage ok' as the last line on success.
cd "$(dirname "$0")/../.." || exit 1
sh setup.sh --packages hardening check || { echo "fuzz: 0 passed, 1 failed (installing clang failed)"; exit 1; }
sh tests/fuzz/run.sh "${FUZZ_SECONDS:-30}" && echo '=== stage ok'
