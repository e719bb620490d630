"""Build of the catena package: the extension catena._catena over libcatena.

libcatena.a of the repository's CMake build (`make`: build/, or $CATENA_BUILD) is linked
into the extension (static: the installed package needs no libcatena.so, no run path and
no LD_LIBRARY_PATH, and keeps working after --target DIR, from any directory, after the
build tree is gone); the libraries libcatena itself links (CHOLMOD, OpenBLAS, ARPACK,
cJSON: Debian's shared libraries) are linked as the catena command links them, read from
CMake's link line of the command. Nothing is downloaded; numpy is not needed to build
(the extension hands out its arrays through the buffer protocol).
"""
import os
import re
import shlex
from pathlib import Path

from setuptools import Extension, setup

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
BUILD = Path(os.environ.get("CATENA_BUILD", ROOT / "build")).resolve()
LIB = BUILD / "libcatena.a"

# The link line of the catena command: what follows libcatena.a is what it needs.
FALLBACK_LIBS = ["-lcholmod", "-lsuitesparseconfig", "-larpack", "-lcjson", "-llapack", "-lblas", "-lm"]


def link_libraries():
    try:
        words = shlex.split((BUILD / "CMakeFiles" / "catena_cli.dir" / "link.txt").read_text())
    except OSError:
        return FALLBACK_LIBS
    tail = [w for w in words[words.index("libcatena.a") + 1:]] if "libcatena.a" in words else []
    return tail or FALLBACK_LIBS


def version():
    text = (ROOT / "CMakeLists.txt").read_text()
    m = re.search(r"project\(catena\s+VERSION\s+([0-9.]+)", text)
    return m.group(1) if m else "0"


def sanitized():
    try:
        cache = (BUILD / "CMakeCache.txt").read_text()
    except OSError:
        return False
    return re.search(r"^CTN_(SANITIZE|FUZZ):BOOL=ON", cache, re.M) is not None


if not LIB.exists():
    raise SystemExit(f"catena: {LIB} not found: build the library first (`make` in {ROOT}), "
                     "or set CATENA_BUILD to the CMake build directory")
if sanitized():
    raise SystemExit(f"catena: {BUILD} is a sanitizer build; build the package from a plain one (`make`)")

SOURCES = sorted(str(p.relative_to(HERE)) for p in (HERE / "src").glob("*.c"))
HEADERS = [str(p) for p in (ROOT / "include").rglob("*.h")] + [str(p) for p in (HERE / "src").glob("*.h")]

ext = Extension(
    "catena._catena",
    sources=SOURCES,
    include_dirs=[str(ROOT / "include"), str(BUILD / "include")],
    extra_objects=[str(LIB)],
    extra_compile_args=["-std=c11", "-Wall", "-Wextra", "-Werror", "-Wno-missing-field-initializers",
                        "-Wno-cast-function-type"],
    # The library's symbols stay inside the extension (no clash with another libcatena).
    extra_link_args=["-Wl,--exclude-libs,ALL"] + link_libraries(),
    depends=[str(LIB)] + HEADERS,
)

setup(
    name="catena",
    version=version(),
    packages=["catena"],
    install_requires=["numpy"],
    python_requires=">=3.10",   # Py_NewRef, PyModule_AddObjectRef
    ext_modules=[ext],
    # Build products go to the CMake build directory, not into the source tree.
    options={"build": {"build_base": str(BUILD / "python")}},
)
