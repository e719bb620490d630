/*
 * catena/export.h - which declarations libcatena.so exports.
 *
 * The library is compiled with -fvisibility=hidden: a function is exported from the
 * shared library only when its declaration lies between CTN_API_BEGIN and CTN_API_END,
 * which every public header in include/catena/ puts around its declarations. The
 * internals shared between the library's source files (src/ headers) stay hidden, so the
 * shared library's symbol table is exactly the public API (tests/cli/install.sh checks
 * it). With compilers other than GCC and Clang the markers expand to nothing.
 * core.h includes this header, and every other public header includes core.h.
 */
#ifndef CATENA_EXPORT_H
#define CATENA_EXPORT_H

#if defined(__GNUC__) || defined(__clang__)
#define CTN_API_BEGIN _Pragma("GCC visibility push(default)")
#define CTN_API_END _Pragma("GCC visibility pop")
#else
#define CTN_API_BEGIN
#define CTN_API_END
#endif

#endif
