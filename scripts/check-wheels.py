#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Checks the wheels scripts/build-wheels.sh made, without running them.

For each wheel: its tags parse; it holds one extension module, named as the
tags say (.cpython-310-x86_64-linux-gnu.so, .abi3.so, .pyd, ...), built for
the tags' processor; and the module needs from the system only what the
platform tag promises:
  Linux    auditwheel show: consistent with the wheel's manylinux tag;
  Windows  the DLLs it imports: KERNEL32, the C runtime (api-ms-win-crt-*),
           and python3.dll (abi3) or python3X.dll (that version), nothing else;
  and on both the core's symbols hidden (exported: PyInit__core, no nv::);
  macOS    its load commands: libSystem only; its minimum macOS (LC_BUILD_VERSION
           or LC_VERSION_MIN_MACOSX) no later than the tag's.
Then `twine check` on every file (the README renders, the metadata is
complete). One line a file; the exit status is 1 if any check failed.

  python3 scripts/check-wheels.py build-wheels/wheelhouse
Needs (scripts/build-wheels-requirements.txt): packaging, auditwheel,
pefile, macholib, twine.
"""
import re
import subprocess
import sys
import zipfile
from pathlib import Path

from packaging.utils import parse_wheel_filename

ELF_MACHINES = {62: "x86_64", 183: "aarch64"}


def module_of(wheel):
    names = [n for n in zipfile.ZipFile(wheel).namelist()
             if re.match(r"narrowvolume/_core\..*(so|pyd)$", n)]
    return names


def expected_suffix(interpreter, abi, platform):
    version = interpreter[2:]
    if platform.startswith("win"):
        return ".pyd" if abi == "abi3" else f".cp{version}-win_amd64.pyd"
    if abi == "abi3":
        return ".abi3.so"
    if platform.startswith("macosx"):
        return f".cpython-{version}-darwin.so"
    arch = "aarch64" if platform.endswith("aarch64") else "x86_64"
    return f".cpython-{version}-{arch}-linux-gnu.so"


def hidden_core(exports):
    """Why the exported symbols are wrong: the module exports PyInit__core;
    the core's (namespace nv, mangled N2nv) stay hidden, so that they never
    meet another library's in the same process. (nanobind exports its own
    exception types, and the Linux modules libc++'s operator new and delete:
    theirs, not ours.)"""
    if "PyInit__core" not in exports:
        return "does not export PyInit__core"
    ours = [name for name in exports if re.search(r"^_ZN[KVR]*2nv|N2nv", name)]
    return f"exports the core's symbols: {ours[:3]}" if ours else ""


def check_linux(wheel, data, platform):
    import io
    from elftools.elf.elffile import ELFFile

    arch = "aarch64" if platform.endswith("aarch64") else "x86_64"
    machine = int.from_bytes(data[18:20], "little")
    if ELF_MACHINES.get(machine) != arch:
        return f"ELF machine {machine}, not {arch}"
    symbols = ELFFile(io.BytesIO(data)).get_section_by_name(".dynsym").iter_symbols()
    hidden = hidden_core([s.name for s in symbols if s["st_shndx"] != "SHN_UNDEF" and s["st_info"]["bind"] != "STB_LOCAL"])
    if hidden:
        return hidden
    shown = subprocess.run([sys.executable, "-m", "auditwheel", "show", str(wheel)], capture_output=True, text=True)
    words = " ".join(shown.stdout.split())
    if f'consistent with the following platform tag: "manylinux_2_17_{arch}"' not in words:
        return "auditwheel show: " + (words or shown.stderr.strip())[:300]
    return f"manylinux_2_17_{arch} (auditwheel show)"


def check_windows(data, abi, interpreter):
    import pefile
    pe = pefile.PE(data=data)
    if pe.FILE_HEADER.Machine != 0x8664:
        return f"PE machine {pe.FILE_HEADER.Machine:#x}, not AMD64"
    python_dll = "python3.dll" if abi == "abi3" else f"python{interpreter[2:]}.dll"
    dlls = sorted(entry.dll.decode().lower() for entry in pe.DIRECTORY_ENTRY_IMPORT)
    others = [d for d in dlls if d not in ("kernel32.dll", python_dll) and not d.startswith("api-ms-win-crt-")]
    if others or python_dll not in dlls:
        return f"imports {', '.join(dlls)}"
    exports = [s.name.decode() for s in pe.DIRECTORY_ENTRY_EXPORT.symbols if s.name]
    hidden = hidden_core(exports)
    if hidden:
        return hidden
    return "imports " + ", ".join(d.replace(".dll", "") for d in dlls if not d.startswith("api-ms-win-crt-")) + " + UCRT"


def check_macos(data, platform):
    import tempfile
    from macholib import mach_o
    from macholib.MachO import MachO

    match = re.match(r"macosx_(\d+)_(\d+)_(x86_64|arm64)", platform)
    tag_version = (int(match.group(1)), int(match.group(2)))
    with tempfile.NamedTemporaryFile(suffix=".so") as module:
        module.write(data)
        module.flush()
        headers = MachO(module.name).headers
    if len(headers) != 1:
        return f"{len(headers)} architectures"
    header = headers[0]
    cputype = mach_o.CPU_TYPE_NAMES.get(header.header.cputype, header.header.cputype)
    if cputype != {"x86_64": "x86_64", "arm64": "ARM64"}[match.group(3)]:
        return f"Mach-O for {cputype}, not {match.group(3)}"
    dylibs, minimum = [], None
    for load, command, body in header.commands:
        name = load.get_cmd_name()
        if name in ("LC_LOAD_DYLIB", "LC_LOAD_WEAK_DYLIB"):
            dylibs.append(body.decode(errors="replace").rstrip("\0"))
        elif name in ("LC_BUILD_VERSION", "LC_VERSION_MIN_MACOSX"):
            version = command.minos if name == "LC_BUILD_VERSION" else command.version
            minimum = (version >> 16, (version >> 8) & 0xFF)
    if [d for d in dylibs if not d.startswith("/usr/lib/libSystem")]:
        return f"loads {dylibs}"
    if minimum is None or minimum > tag_version:
        return f"minimum macOS {minimum}, the tag says {tag_version}"
    return f"loads libSystem only; minimum macOS {minimum[0]}.{minimum[1]}"


def check(wheel):
    _, _, _, tags = parse_wheel_filename(wheel.name)
    tags = sorted(tags, key=str)
    interpreter, abi = tags[0].interpreter, tags[0].abi
    platform = tags[-1].platform
    modules = module_of(wheel)
    if len(modules) != 1:
        return False, f"{len(modules)} modules: {modules}"
    suffix = expected_suffix(interpreter, abi, platform)
    if not modules[0].endswith("_core" + suffix):
        return False, f"module {modules[0]}, expected _core{suffix}"
    data = zipfile.ZipFile(wheel).read(modules[0])
    if platform.startswith(("manylinux", "linux")):
        result = check_linux(wheel, data, platform)
        ok = result.startswith("manylinux")
    elif platform.startswith("win"):
        result = check_windows(data, abi, interpreter)
        ok = result.startswith("imports") and "," in result
    else:
        result = check_macos(data, platform)
        ok = result.startswith("loads libSystem")
    return ok, f"{modules[0].split('/')[-1]}: {result}"


def main():
    folder = Path(sys.argv[1])
    wheels = sorted(folder.glob("*.whl"))
    failed = 0
    print(f"{'file':<78} {'kB':>5}  check")
    for wheel in wheels:
        try:
            ok, words = check(wheel)
        except Exception as error:  # a wheel that cannot be read fails, with why
            ok, words = False, f"{type(error).__name__}: {error}"
        failed += not ok
        print(f"{wheel.name:<78} {wheel.stat().st_size // 1024:>5}  {'ok  ' if ok else 'FAIL'} {words}")
    files = [str(p) for p in sorted(folder.iterdir()) if p.suffix in (".whl", ".gz")]
    twine = subprocess.run([sys.executable, "-m", "twine", "check", "--strict", *files],
                           capture_output=True, text=True)
    print(f"twine check --strict, {len(files)} files: {'passed' if twine.returncode == 0 else 'FAILED'}")
    if twine.returncode:
        print(twine.stdout[-3000:], twine.stderr[-2000:])
    if not wheels:
        print("no wheels")
    sys.exit(1 if failed or twine.returncode or not wheels else 0)


if __name__ == "__main__":
    main()
