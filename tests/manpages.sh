#!/bin/sh
# manpages.sh - every exported function (tests/symbols.txt) has a section-3
# page, man/NAME.3, either a page of its own or a `.so man3/PAGE.3` link to
# a grouped page that names it in its NAME section; every page is installed
# (dist_man_MANS, passed as ATRBVH_MANS by make check); and every page
# renders without a warning with `groff -man -ww -z` (with -t when it has a
# table) and `mandoc -Tlint -W warning` when mandoc is installed (mandoc's
# style notes are shown but not fatal).  Run by `make check`.
set -u
: "${ATRBVH_SRCDIR:?}"
man=$ATRBVH_SRCDIR/man
passed=0
failed=0
ko() { echo "manpages: FAILED: $*"; failed=$((failed + 1)); }
ok() { passed=$((passed + 1)); }

# The page a file resolves to: itself, or the target of its `.so` line.
resolve() {
    so=$(sed -n 's/^\.so[ \t]\{1,\}//p' "$1" | head -n 1)
    if [ -n "$so" ]; then echo "$man/$(basename "$so")"; else echo "$1"; fi
}

# ----------------------------------------------- every function has a page
for sym in $(grep -v '^#' "$ATRBVH_SRCDIR/tests/symbols.txt"); do
    f=$man/$sym.3
    if [ ! -f "$f" ]; then ko "$sym: no man/$sym.3"; continue; fi
    page=$(resolve "$f")
    if [ ! -f "$page" ]; then ko "$sym: man/$sym.3 links to missing $(basename "$page")"; continue; fi
    # The NAME section (up to the next .SH) must name the function, so that
    # whatis/apropos find it.
    if ! awk '/^\.SH/ { n = ($2 == "NAME") ; next } n' "$page" |
            sed 's/\\-/-/g; s/\\//g' | tr ',' ' ' | grep -qw -- "$sym"; then
        ko "$sym: $(basename "$page")'s NAME section does not name it"; continue
    fi
    ok
done

# ------------- atrbvh(1) documents every command and option of the tool
# Commands: the names in tools/main.c's command table; options: every
# "--name" string literal in tools/main.c, tools/cli*.c and tools/bench/*.c
# (the installed tool).  The page's escapes (\-, \fB...)
# are removed before looking.
page1=$(sed 's/\\f[BIRP]//g; s/\\f(..//g; s/\\-/-/g; s/\\(em/-/g' "$man/atrbvh.1")
for cmd in $(sed -n 's/.*{ *"\([a-z][a-z-]*\)", *cli_[a-z_]* *}.*/\1/p; s/.*{"\([a-z][a-z-]*\)", cli_.*/\1/p' \
                 "$ATRBVH_SRCDIR"/tools/main.c | sort -u); do
    if printf '%s\n' "$page1" | grep -q -e "atrbvh $cmd\b" -e "^\.B $cmd\$"; then ok
    else ko "atrbvh(1) does not document the command '$cmd'"; fi
done
for opt in $(cat "$ATRBVH_SRCDIR"/tools/main.c "$ATRBVH_SRCDIR"/tools/cli*.c "$ATRBVH_SRCDIR"/tools/bench/*.c | grep -o '"--[a-z][a-z0-9-]*' | tr -d '"' | sort -u); do
    if printf '%s\n' "$page1" | grep -q -e "$opt\b"; then ok
    else ko "atrbvh(1) does not document the option '$opt'"; fi
done

# ------------------------------------------------ every page is installed
if [ -n "${ATRBVH_MANS:-}" ]; then
    for f in "$man"/*.[0-9]; do
        n=man/$(basename "$f")
        case " $ATRBVH_MANS " in
            *" $n "*) ok ;;
            *) ko "$n is not in dist_man_MANS (not installed, not in the tarball)" ;;
        esac
    done
fi

# -------------------------------------- every page renders without warnings
have_mandoc=no
command -v mandoc >/dev/null 2>&1 && have_mandoc=yes
command -v groff >/dev/null 2>&1 || { echo "manpages: no groff; rendering not checked"; }
for f in "$man"/*.[0-9]; do
    page=$(resolve "$f")
    [ "$page" = "$f" ] || continue     # a .so link: its target is checked
    name=$(basename "$f")
    if command -v groff >/dev/null 2>&1; then
        t=
        grep -q '^\.TS' "$f" && t=-t
        msg=$(LC_ALL=C.UTF-8 groff -man $t -ww -z -K utf8 "$f" 2>&1)
        if [ -n "$msg" ]; then ko "groff warns on $name:"; echo "$msg"; else ok; fi
    fi
    if [ $have_mandoc = yes ]; then
        msg=$(mandoc -Tlint -W warning "$f" 2>&1)
        if [ -n "$msg" ]; then ko "mandoc warns on $name:"; echo "$msg"; else ok; fi
        mandoc -Tlint -W style "$f" 2>&1 | sed 's/^/manpages: note: /'
    fi
done

echo "manpages: $passed passed, $failed failed"
[ $failed -eq 0 ]
