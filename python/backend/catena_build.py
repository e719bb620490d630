"""The build backend of the catena package (PEP 517), in the tree so that pip builds it
offline with any Python that has setuptools, with or without the `wheel` package (a pyenv
or venv Python often lacks it, and no index is reachable): setuptools compiles (setup.py
build: build_py + build_ext), and this file packs the result as a wheel itself (a zip
with a .dist-info: METADATA, WHEEL, RECORD). sdists are setuptools' own."""
import base64
import hashlib
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import zipfile

from setuptools import build_meta as _setuptools

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NAME = "catena"


def _version():
    with open(os.path.join(HERE, "..", "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(catena\s+VERSION\s+([0-9.]+)", f.read())
    return m.group(1) if m else "0"


def _tag():
    impl = {"cpython": "cp"}.get(sys.implementation.name, sys.implementation.name)
    ver = f"{sys.version_info[0]}{sys.version_info[1]}"
    plat = re.sub(r"[-.]", "_", sysconfig.get_platform())
    return f"{impl}{ver}-{impl}{ver}-{plat}"


def _metadata():
    return (f"Metadata-Version: 2.1\nName: {NAME}\nVersion: {_version()}\n"
            "Summary: Geometrically non-linear static analysis of 3D cable structures (libcatena)\n"
            "Requires-Python: >=3.10\nRequires-Dist: numpy\n"
            "Provides-Extra: pandas\nRequires-Dist: pandas; extra == \"pandas\"\n"
            "Provides-Extra: plot\nRequires-Dist: matplotlib; extra == \"plot\"\n")


def _wheel_text():
    return f"Wheel-Version: 1.0\nGenerator: catena_build\nRoot-Is-Purelib: false\nTag: {_tag()}\n"


def _distinfo():
    return f"{NAME}-{_version()}.dist-info"


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    d = os.path.join(metadata_directory, _distinfo())
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "METADATA"), "w", encoding="utf-8") as f:
        f.write(_metadata())
    with open(os.path.join(d, "WHEEL"), "w", encoding="utf-8") as f:
        f.write(_wheel_text())
    return _distinfo()


def _digest(data):
    return "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    tmp = tempfile.mkdtemp(prefix="catena-wheel-")
    try:
        lib = os.path.join(tmp, "lib")
        subprocess.run([sys.executable, "setup.py", "-q", "build", f"--build-lib={lib}"], cwd=HERE, check=True)
        name = f"{NAME}-{_version()}-{_tag()}.whl"
        files = []
        for root, _, names in os.walk(lib):
            for n in sorted(names):
                full = os.path.join(root, n)
                files.append((os.path.relpath(full, lib).replace(os.sep, "/"), full))
        di = _distinfo()
        extra = {f"{di}/METADATA": _metadata().encode(), f"{di}/WHEEL": _wheel_text().encode(),
                 f"{di}/top_level.txt": f"{NAME}\n".encode()}
        record = []
        with zipfile.ZipFile(os.path.join(wheel_directory, name), "w", zipfile.ZIP_DEFLATED) as z:
            for arc, full in sorted(files):
                with open(full, "rb") as f:
                    data = f.read()
                z.writestr(arc, data)
                record.append(f"{arc},{_digest(data)},{len(data)}")
            for arc, data in extra.items():
                z.writestr(arc, data)
                record.append(f"{arc},{_digest(data)},{len(data)}")
            record.append(f"{di}/RECORD,,")
            z.writestr(f"{di}/RECORD", "\n".join(record) + "\n")
        return name
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def build_sdist(sdist_directory, config_settings=None):
    return _setuptools.build_sdist(sdist_directory, config_settings)
