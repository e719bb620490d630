#!/usr/bin/env bash
# tests/cli/install.sh CATENA: the installed library, as a user outside the tree sees it.
#
#   - `cmake --install BUILD --prefix $T/prefix` (BUILD: the directory of CATENA) puts the
#     headers, libcatena.a, libcatena.so (SONAME libcatena.so.0), the catena command and
#     catena.pc where CMAKE_INSTALL_LIBDIR says; with DESTDIR the files go under it and
#     catena.pc still names the prefix;
#   - a C program written here, compiled in $T with `cc $(pkg-config --cflags --libs
#     catena)` (shared library, run with LD_LIBRARY_PATH) and again with `pkg-config
#     --static` against libcatena.a, solves examples/paper/s250.8777.cable: converged, the
#     iteration count of `catena solve --json`, ctn_version() = CATENA_VERSION_STRING;
#   - libcatena.so exports only the public API: every symbol of `nm -D --defined-only`
#     starts with ctn_ and is declared in the installed include/catena/ headers, every
#     function they declare is exported, and internals (ctn_norm, ctn_error, ...) are not;
#   - `catena --version` and `catena version` print "catena VERSION", VERSION the Version
#     of catena.pc; `catena COMMAND --help`, `-h` and `catena help COMMAND` print the
#     command's synopsis and exit codes on stdout and exit 0; `catena help` lists them.
# Run from the repository root (ctest does). Prints "N passed, N failed"; exit 1 on any
# failure. Needs cc, pkg-config, nm and readelf (binutils).
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init install "${1:-}"

BUILD=$(dirname "$BIN")
EX=$PWD/examples/paper/s250.8777.cable
P=$T/prefix
COMMANDS="solve compare study convergence"

# A build with sanitizers (CTN_SANITIZE or CTN_FUZZ) made instrumented libraries: a
# program linking them needs the same runtime.
SAN_FLAGS=()
if grep -Eq '^CTN_(SANITIZE|FUZZ):BOOL=ON' "$BUILD/CMakeCache.txt" 2>/dev/null; then
    # shellcheck disable=SC2054   # one flag with a comma-separated value
    SAN_FLAGS=(-fsanitize=address,undefined -fno-omit-frame-pointer)
fi

# ---- install ------------------------------------------------------------------------------
[ -f "$BUILD/cmake_install.cmake" ] || WHY+=("$BUILD is not a CMake build directory")
cmake --install "$BUILD" --prefix "$P" >"$T/install.log" 2>&1 ||
    WHY+=("cmake --install failed: $(tail -5 "$T/install.log")")
PC=$(find "$P" -name catena.pc -path '*/pkgconfig/*' | head -1)
[ -n "$PC" ] || WHY+=("no pkgconfig/catena.pc under the prefix")
PCDIR=$(dirname "${PC:-$P/lib/pkgconfig/catena.pc}")
pc() { PKG_CONFIG_PATH=$PCDIR pkg-config "$@"; }
LIBDIR=$(pc --variable=libdir catena 2>/dev/null)
INCDIR=$(pc --variable=includedir catena 2>/dev/null)
VERSION=$(pc --modversion catena 2>/dev/null)
[ "$LIBDIR" = "$(dirname "$PCDIR")" ] || WHY+=("catena.pc: libdir '$LIBDIR', but it lies in $PCDIR")
[ "$INCDIR" = "$P/include" ] || WHY+=("catena.pc: includedir '$INCDIR', expected $P/include")
echo "$VERSION" | grep -Eq '^[0-9]+\.[0-9]+\.[0-9]+$' || WHY+=("catena.pc: Version '$VERSION'")
for f in "$P/bin/catena" "$P/include/catena.h" "$LIBDIR/libcatena.a" "$LIBDIR/libcatena.so" \
         "$LIBDIR/libcatena.so.0" "$LIBDIR/libcatena.so.$VERSION"; do
    [ -e "$f" ] || WHY+=("not installed: ${f#"$P"/}")
done
for h in include/catena/*.h export.h version.h; do
    [ -f "$P/include/catena/${h##*/}" ] || WHY+=("not installed: include/catena/${h##*/}")
done
soname=$(readelf -d "$LIBDIR/libcatena.so" 2>/dev/null | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
[ "$soname" = libcatena.so.0 ] || WHY+=("SONAME '$soname', expected libcatena.so.0")
grep -q "CATENA_VERSION_STRING \"$VERSION\"" "$P/include/catena/version.h" 2>/dev/null ||
    WHY+=("installed version.h does not say $VERSION")
finish "cmake --install --prefix"

# DESTDIR: the files are staged under it, catena.pc names the final prefix.
DESTDIR=$T/stage cmake --install "$BUILD" --prefix /opt/catena-test >"$T/stage.log" 2>&1 ||
    WHY+=("cmake --install with DESTDIR failed: $(tail -5 "$T/stage.log")")
[ -f "$T/stage/opt/catena-test/include/catena.h" ] || WHY+=("DESTDIR: no include/catena.h under the staging dir")
[ -x "$T/stage/opt/catena-test/bin/catena" ] || WHY+=("DESTDIR: no bin/catena under the staging dir")
spc=$(find "$T/stage" -name catena.pc | head -1)
[ -n "$spc" ] && grep -qx 'prefix=/opt/catena-test' "$spc" || WHY+=("DESTDIR: catena.pc does not name the prefix")
[ -e /opt/catena-test ] && WHY+=("DESTDIR: files written outside the staging directory")
finish "DESTDIR"

# ---- a program built against the installed library -----------------------------------------
cat >"$T/app.c" <<'EOF'
/* Outside the tree: solve a model with the installed catena. */
#include <catena.h>

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_summary sum;
    if (argc != 2 || ctn_ctx_create(&ctx)) return 2;
    ctn_solve_options opt;
    int rc = ctn_read_file(ctx, argv[1], &m, &opt);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    if (rc) {
        fprintf(stderr, "app: %s\n", ctn_ctx_message(ctx));
    } else {
        ctn_solution_summary(s, &sum);
        printf("version %s %s\n", ctn_version(), strcmp(ctn_version(), CATENA_VERSION_STRING) ? "mismatch" : "ok");
        printf("iterations %d\n", sum.iterations);
        printf("converged %d\n", sum.reason == CTN_CONVERGED);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return rc ? 1 : 0;
}
EOF
want_it=$("$BIN" solve "$EX" --json 2>/dev/null | sed -n 's/^[[:space:]]*"iterations":[[:space:]]*\([0-9]*\),*$/\1/p' | head -1)
[ -n "$want_it" ] || echo "install.sh: no iteration count in catena solve --json" >&2

# check_app NAME: the output of $T/NAME.
check_app() {
    local out=$T/$1.out
    grep -qx "version $VERSION ok" "$out" || WHY+=("$1: version line wrong: $(head -3 "$out")")
    grep -qx "converged 1" "$out" || WHY+=("$1: not converged: $(cat "$out")")
    grep -qx "iterations ${want_it:-?}" "$out" ||
        WHY+=("$1: $(grep iterations "$out"), catena solve took ${want_it:-?}")
}

cflags=(-std=c11 -Wall -Wextra -pedantic -Werror "${SAN_FLAGS[@]}")
# shared: cc app.c $(pkg-config --cflags --libs catena)
# shellcheck disable=SC2046   # the flags are words
(cd "$T" && cc "${cflags[@]}" -o app_shared app.c $(pc --cflags --libs catena)) >"$T/cc.log" 2>&1 ||
    WHY+=("cc against libcatena.so failed: $(head -c 600 "$T/cc.log")")
if [ -x "$T/app_shared" ]; then
    LD_LIBRARY_PATH=$LIBDIR "$T/app_shared" "$EX" >"$T/app_shared.out" 2>"$T/app_shared.err" ||
        WHY+=("app_shared failed: $(head -c 300 "$T/app_shared.err")")
    check_app app_shared
    LD_LIBRARY_PATH=$LIBDIR ldd "$T/app_shared" 2>/dev/null | grep -q "libcatena.so.0 => $LIBDIR/" ||
        WHY+=("app_shared does not load $LIBDIR/libcatena.so.0")
fi
finish "pkg-config --cflags --libs catena (shared)"

# static: the flags of pkg-config --static, with libcatena.a in place of -lcatena (the
# linker would otherwise take libcatena.so from the same directory)
static_flags=$(pc --static --cflags --libs catena)
echo " $static_flags " | grep -q -- ' -lcholmod ' || WHY+=("pkg-config --static lacks -lcholmod: $static_flags")
static_flags=${static_flags/-lcatena/-l:libcatena.a}
# shellcheck disable=SC2086   # the flags are words
(cd "$T" && cc "${cflags[@]}" -o app_static app.c $static_flags) >"$T/ccs.log" 2>&1 ||
    WHY+=("cc --static flags against libcatena.a failed: $(head -c 600 "$T/ccs.log")")
if [ -x "$T/app_static" ]; then
    readelf -d "$T/app_static" | grep -q 'libcatena' && WHY+=("app_static needs libcatena.so")
    "$T/app_static" "$EX" >"$T/app_static.out" 2>"$T/app_static.err" ||
        WHY+=("app_static failed: $(head -c 300 "$T/app_static.err")")
    check_app app_static
fi
finish "pkg-config --static --cflags --libs catena (libcatena.a)"

# ---- exported symbols -----------------------------------------------------------------------
# Functions the public headers declare (comments stripped; perl-base is essential).
cat "$P"/include/catena/*.h | perl -0777 -pe 's{/\*.*?\*/}{ }gs; s{//[^\n]*}{}g' |
    grep -oE '\bctn_[A-Za-z0-9_]+[[:space:]]*\(' | sed 's/[[:space:]]*($//' | sort -u >"$T/declared"
nm -D --defined-only "$LIBDIR/libcatena.so" 2>/dev/null | awk 'NF >= 3 { print $3 }' | sed 's/@.*//' |
    sort -u >"$T/exported"
[ "$(wc -l <"$T/declared")" -gt 50 ] || WHY+=("only $(wc -l <"$T/declared") functions found in the headers")
[ "$(wc -l <"$T/exported")" -gt 50 ] || WHY+=("only $(wc -l <"$T/exported") symbols exported")
grep -qx ctn_version "$T/exported" || WHY+=("ctn_version is not exported")
bad=$(grep -v '^ctn_' "$T/exported" | head -20 | tr '\n' ' ')
[ -z "$bad" ] || WHY+=("exported without the ctn_ prefix: $bad")
bad=$(comm -23 "$T/exported" "$T/declared" | head -20 | tr '\n' ' ')
[ -z "$bad" ] || WHY+=("exported but not declared in include/catena/: $bad")
bad=$(comm -13 "$T/exported" "$T/declared" | head -20 | tr '\n' ' ')
[ -z "$bad" ] || WHY+=("declared in include/catena/ but not exported: $bad")
for internal in ctn_norm ctn_dot ctn_now ctn_error ctn_malloc; do
    grep -qx "$internal" "$T/exported" && WHY+=("internal $internal is exported")
done
finish "libcatena.so exports the public API only"

# ---- version and help -------------------------------------------------------------------------
for b in "$BIN" "$P/bin/catena"; do
    for v in --version version; do
        out=$("$b" "$v" 2>"$T/err")
        rc=$?
        [ "$rc" = 0 ] || WHY+=("$b $v: exit $rc")
        [ "$out" = "catena $VERSION" ] || WHY+=("$b $v: '$out', expected 'catena $VERSION'")
        [ -s "$T/err" ] && WHY+=("$b $v: stderr: $(head -c 200 "$T/err")")
    done
done
finish "catena --version = catena.pc Version"

for cmd in $COMMANDS; do
    for form in "$cmd --help" "$cmd -h" "help $cmd" "$cmd examples/paper/s250.8777.cable --help"; do
        # shellcheck disable=SC2086
        "$BIN" $form >"$T/out" 2>"$T/err"
        rc=$?
        [ "$rc" = 0 ] || WHY+=("catena $form: exit $rc")
        head -1 "$T/out" | grep -q "^usage: catena $cmd " || WHY+=("catena $form: no synopsis: $(head -1 "$T/out")")
        grep -q '^exit codes:' "$T/out" || WHY+=("catena $form: no exit codes")
        grep -q -- '--help' "$T/out" || WHY+=("catena $form: --help not listed")
        [ -s "$T/err" ] && WHY+=("catena $form: stderr: $(head -c 200 "$T/err")")
    done
    # every option the command's synopsis names has its line
    sed -n '1,/^$/p' "$T/out" | grep -oE -- '(^| |\[)-{1,2}[a-z-]+' | tr -d ' [' | sort -u >"$T/opts"
    while read -r o; do
        grep -Eq "^  +([^ ]+, )?$o( |,|$)" "$T/out" || WHY+=("catena $cmd --help: no line for $o")
    done <"$T/opts"
    finish "catena $cmd --help"
done

"$BIN" help >"$T/out" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("exit $rc")
for cmd in $COMMANDS; do grep -q "^  $cmd " "$T/out" || WHY+=("does not list $cmd"); done
grep -q 'COMMAND --help' "$T/out" || WHY+=("does not mention catena COMMAND --help")
grep -q -- '--version' "$T/out" || WHY+=("does not mention --version")
"$BIN" help frobnicate >/dev/null 2>&1
rc=$?
[ "$rc" = 1 ] || WHY+=("catena help frobnicate: exit $rc, expected 1")
finish "catena help"

cli_summary
