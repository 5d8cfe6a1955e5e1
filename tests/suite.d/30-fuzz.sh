#!/bin/sh
# libFuzzer harnesses (tests/fuzz/): each for $FUZZ_SECONDS (30) seconds
# from its seed corpus, under ASan and UBSan.
# Contract: print '=== stage ok' as the last line on success.
sh tests/fuzz/run.sh "${FUZZ_SECONDS:-30}" && echo '=== stage ok'
