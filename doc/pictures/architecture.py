# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Draws doc/images/architecture.svg: the core's layers (Filters/Core's
folders, bottom up), the headers whose equations the CPU stages and the
device kernels share, and the engine seam in Run. A drawing, not a
measurement: plain SVG from the standard library.

    python3 doc/pictures/architecture.py doc/images/architecture.svg
"""
layers = [  # bottom first: (folder, what, shared headers)
    ("Common", "grid, parameters, memory", "nvHostDevice.h (NV_HD)  nvBits.h"),
    ("Parallel", "threads, processes, slabs", ""),
    ("Points", "sampling, gap closing", ""),
    ("Band", "truncated distance (eq. 6, 7), narrow band", "nvPointSort.h  nvBandTerms.h"),
    ("Scheme", "Allen-Cahn steps (eq. 2-5, 10-12)", "nvSchemeTerms.h  nvTimeLoop.h"),
    ("Output", "dense phi, surface, sheets, pieces, part", "nvSurfaceTerms.h  nvVolumeTerms.h"),
    ("Device", "kernels + host and CUDA launchers", ""),
    ("Run", "settings, plan, the run, the engines", ""),
]
W, row, top = 940, 58, 70
H = top + row * len(layers) + 30
out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d" '
       'font-family="DejaVu Sans, Arial, sans-serif" font-size="13">' % (W, H, W, H),
       '<rect width="100%" height="100%" fill="white"/>',
       '<defs><marker id="a" markerWidth="10" markerHeight="8" refX="9" refY="4" orient="auto">'
       '<path d="M0,0 L10,4 L0,8 z" fill="#444"/></marker></defs>',
       '<text x="20" y="28" font-size="16" font-weight="bold">Filters/Core: layers (a file includes only its own layer and those below) and the engine seam</text>',
       '<text x="20" y="50" fill="#555">Shaded headers hold the equations written once (NV_HD: host and GPU); the CPU stages and the device kernels both call them.</text>']
y_of = {}
for i, (folder, what, shared) in enumerate(layers):
    y = top + row * (len(layers) - 1 - i)
    y_of[folder] = y
    fill = "#eef3fb" if folder not in ("Device", "Run") else ("#fdf0e6" if folder == "Device" else "#eef8ee")
    out.append('<rect x="20" y="%d" width="900" height="%d" fill="%s" stroke="#99a"/>' % (y, row - 6, fill))
    out.append('<text x="32" y="%d" font-weight="bold">%s</text>' % (y + 20, folder))
    out.append('<text x="32" y="%d" fill="#444" font-size="11">%s</text>' % (y + 36, what))
    if shared:
        out.append('<rect x="330" y="%d" width="300" height="%d" rx="4" fill="#ffe9a8" stroke="#c9a227"/>' % (y + 8, row - 22))
        out.append('<text x="480" y="%d" text-anchor="middle" font-family="DejaVu Sans Mono, monospace" font-size="12">%s</text>' % (y + 29, shared))
# Run: the seam
yr = y_of["Run"]
boxes = [(330, "nvReconstruction (steps 1-9)"), (560, "Engine (nvEngine.h)")]
out.append('<rect x="300" y="%d" width="190" height="30" rx="4" fill="white" stroke="#363"/>' % (yr + 8))
out.append('<text x="395" y="%d" text-anchor="middle" font-size="12">the run: nvReconstruction</text>' % (yr + 28))
out.append('<rect x="520" y="%d" width="120" height="30" rx="4" fill="white" stroke="#363"/>' % (yr + 8))
out.append('<text x="580" y="%d" text-anchor="middle" font-size="12">Engine</text>' % (yr + 28))
out.append('<line x1="490" y1="%d" x2="518" y2="%d" stroke="#444" marker-end="url(#a)"/>' % (yr + 23, yr + 23))
out.append('<rect x="670" y="%d" width="100" height="30" rx="4" fill="white" stroke="#363"/>' % (yr + 8))
out.append('<text x="720" y="%d" text-anchor="middle" font-size="12">CPU engine</text>' % (yr + 28))
out.append('<rect x="790" y="%d" width="120" height="30" rx="4" fill="white" stroke="#363"/>' % (yr + 8))
out.append('<text x="850" y="%d" text-anchor="middle" font-size="12">device engine</text>' % (yr + 28))
out.append('<line x1="640" y1="%d" x2="668" y2="%d" stroke="#444" marker-end="url(#a)"/>' % (yr + 23, yr + 23))
out.append('<path d="M640,%d C700,%d 760,%d 790,%d" fill="none" stroke="#444" marker-end="url(#a)"/>' % (yr + 14, yr - 2, yr - 2, yr + 12))
# device box in Device layer
yd = y_of["Device"]
out.append('<rect x="760" y="%d" width="150" height="30" rx="4" fill="white" stroke="#a63"/>' % (yd + 8))
out.append('<text x="835" y="%d" text-anchor="middle" font-size="11">kernels (2 launchers)</text>' % (yd + 28))
out.append('<text x="300" y="%d" fill="#555" font-size="11">dashed: the CPU engine runs the CPU stages below;</text>' % (yd + 19))
out.append('<text x="300" y="%d" fill="#555" font-size="11">solid: the device engine runs the kernels, which keep only</text>' % (yd + 33))
out.append('<text x="300" y="%d" fill="#555" font-size="11">which node and where to write, and call the shaded terms.</text>' % (yd + 47))
out.append('<line x1="850" y1="%d" x2="850" y2="%d" stroke="#444" marker-end="url(#a)"/>' % (yr + 38, yd + 8))
# CPU engine down to the CPU stages (Output)
out.append('<line x1="700" y1="%d" x2="700" y2="%d" stroke="#363" stroke-dasharray="4,3" marker-end="url(#a)"/>' % (yr + 38, y_of["Output"] + 8))
out.append('<text x="650" y="%d" fill="#363" font-size="11">CPU stages</text>' % (y_of["Output"] + 24))
# kernels call the shared terms
for folder in ("Output", "Scheme", "Band"):
    yt = y_of[folder]
    out.append('<path d="M760,%d C700,%d 680,%d 632,%d" fill="none" stroke="#a63" marker-end="url(#a)"/>' % (yd + 30, yd + 34, yt + 25, yt + 25))
out.append('</svg>')
import sys
open(sys.argv[1], "w").write("\n".join(out) + "\n")
