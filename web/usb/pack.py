#!/usr/bin/env python3
"""Packs the release web app (dist/) into shoal-usb.zip: Shoal for a USB
stick or a computer with no network (`./dev usb`). The zip holds one folder,
shoal-usb/, with the app in shoal/, the server serve.py and the start
scripts of this folder, and README.txt.

    python3 web/usb/pack.py dist shoal-usb.zip
"""

import os
import sys
import time
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = "shoal-usb"
# Beside the app: (file in web/usb/, executable?).
FILES = [("serve.py", True), ("start.sh", True), ("start.cmd", False), ("README.txt", False)]


def add(zf, path, name, executable):
    info = zipfile.ZipInfo(name, date_time=time.localtime(os.path.getmtime(path))[:6])
    info.compress_type = zipfile.ZIP_DEFLATED
    # Unix permissions, so start.sh runs after unzip on macOS and Linux.
    info.external_attr = (0o100755 if executable else 0o100644) << 16
    with open(path, "rb") as f:
        zf.writestr(info, f.read())


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    dist, out = sys.argv[1], sys.argv[2]
    if not os.path.isfile(os.path.join(dist, "index.html")):
        sys.exit(f"{dist}/index.html is missing: build the web app first (trunk build --release).")
    with zipfile.ZipFile(out, "w") as zf:
        for name, executable in FILES:
            add(zf, os.path.join(HERE, name), f"{TOP}/{name}", executable)
        for root, _dirs, files in sorted(os.walk(dist)):
            for name in sorted(files):
                # The precompressed copies (tools/web-finish) are for web servers;
                # the stick's local server sends the files themselves.
                if name.endswith((".br", ".gz")):
                    continue
                path = os.path.join(root, name)
                rel = os.path.relpath(path, dist).replace(os.sep, "/")
                add(zf, path, f"{TOP}/shoal/{rel}", False)
    print(f"{out}: {os.path.getsize(out) / 2**20:.1f} MiB")


if __name__ == "__main__":
    main()
