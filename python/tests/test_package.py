"""The package as the build leaves it: its modules byte-compiled, so that `import granular` does not
compile them on every start where nothing may write bytecode (PYTHONDONTWRITEBYTECODE, read-only
installs). The ctest environment sets PYTHONDONTWRITEBYTECODE, so no test run writes them either."""
import importlib.util
import os
import pathlib
import struct

import granular


def test_every_module_has_current_bytecode():
    package = pathlib.Path(granular.__file__).parent
    sources = sorted(package.rglob("*.py"))
    assert len(sources) > 5
    stale = []
    for source in sources:
        cached = pathlib.Path(importlib.util.cache_from_source(str(source)))
        if not cached.exists():
            stale.append(f"{source.name}: no {cached.name}")
            continue
        header = cached.read_bytes()[:16]
        flags, mtime, size = struct.unpack("<III", header[4:16])
        stat = source.stat()
        # Unchecked-hash pycs (flags != 0) are valid whatever the time; timestamp ones must match.
        if flags == 0 and (mtime != int(stat.st_mtime) & 0xFFFFFFFF or size != stat.st_size & 0xFFFFFFFF):
            stale.append(f"{source.name}: bytecode of another version")
    assert not stale, stale


def test_this_run_writes_no_bytecode():
    assert os.environ.get("PYTHONDONTWRITEBYTECODE"), "ctest sets PYTHONDONTWRITEBYTECODE for the python tests"
