# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The accuracy test shapes of the paper's Table 1, sampled as point clouds,
with the exact distance from any point to their inner offset surface.

Unit-size shapes in the box [0, 1]^3: a cube of side 1, a sphere of diameter 1
and a cylinder of diameter 1 and height 1 (axis along z). Points are spread
over the surface about `spacing` apart (regular grids on flat faces, a
Fibonacci lattice on the sphere, rings on the cylinder's side).
"""
import math

import numpy as np

CENTER = np.array([0.5, 0.5, 0.5])


def _square_grid(n):
    u = (np.arange(n + 1) / n)
    a, b = np.meshgrid(u, u, indexing="ij")
    return a.ravel(), b.ravel()


def cube_points(spacing):
    n = int(math.ceil(1.0 / spacing))
    a, b = _square_grid(n)
    zeros, ones = np.zeros_like(a), np.ones_like(a)
    faces = [np.c_[zeros, a, b], np.c_[ones, a, b], np.c_[a, zeros, b], np.c_[a, ones, b],
             np.c_[a, b, zeros], np.c_[a, b, ones]]
    return np.unique(np.round(np.vstack(faces), 12), axis=0)


def sphere_points(spacing, radius=0.5, count=None):
    """A Fibonacci lattice about `spacing` apart, or of exactly `count` points."""
    n = count or int(math.ceil(4.0 * math.pi * radius ** 2 / spacing ** 2))
    i = np.arange(n) + 0.5
    polar = np.arccos(1.0 - 2.0 * i / n)
    azimuth = math.pi * (1.0 + 5.0 ** 0.5) * i
    unit = np.c_[np.cos(azimuth) * np.sin(polar), np.sin(azimuth) * np.sin(polar), np.cos(polar)]
    return CENTER + radius * unit


def _disk(spacing, radius, z):
    points = [np.array([[0.0, 0.0]])]
    rings = int(math.ceil(radius / spacing))
    for k in range(1, rings + 1):
        r = radius * k / rings
        m = int(math.ceil(2.0 * math.pi * r / spacing))
        t = 2.0 * math.pi * np.arange(m) / m
        points.append(np.c_[r * np.cos(t), r * np.sin(t)])
    xy = np.vstack(points)
    return np.c_[xy + 0.5, np.full(len(xy), z)]


def cylinder_points(spacing, radius=0.5, height=1.0):
    m = int(math.ceil(2.0 * math.pi * radius / spacing))
    levels = int(math.ceil(height / spacing))
    t = 2.0 * math.pi * np.arange(m) / m
    z = height * np.arange(levels + 1) / levels
    tt, zz = np.meshgrid(t, z, indexing="ij")
    side = np.c_[0.5 + radius * np.cos(tt.ravel()), 0.5 + radius * np.sin(tt.ravel()), zz.ravel()]
    return np.vstack([side, _disk(spacing, radius, 0.0), _disk(spacing, radius, height)])


def _box_sdf(x, lo, hi):
    """Signed Euclidean distance to the box [lo, hi]^3 (negative inside)."""
    c, half = (lo + hi) / 2.0, (hi - lo) / 2.0
    q = np.abs(x - c) - half
    outside = np.linalg.norm(np.maximum(q, 0.0), axis=1)
    inside = np.minimum(q.max(axis=1), 0.0)
    return outside + inside


def _cylinder_sdf(x, radius, z0, z1):
    """Signed Euclidean distance to the solid cylinder around the z axis through (0.5, 0.5)."""
    r = np.hypot(x[:, 0] - 0.5, x[:, 1] - 0.5)
    dr = r - radius
    dz = np.abs(x[:, 2] - (z0 + z1) / 2.0) - (z1 - z0) / 2.0
    outside = np.hypot(np.maximum(dr, 0.0), np.maximum(dz, 0.0))
    inside = np.minimum(np.maximum(dr, dz), 0.0)
    return outside + inside


def rotation(about_z=0.5, about_x=0.3):
    """A fixed rotation that puts no face of the cube along a grid plane."""
    cz, sz, cx, sx = math.cos(about_z), math.sin(about_z), math.cos(about_x), math.sin(about_x)
    rz = np.array([[cz, -sz, 0.0], [sz, cz, 0.0], [0.0, 0.0, 1.0]])
    rx = np.array([[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]])
    return rx @ rz


ROTATION = rotation()


def _unrotate(x):
    return (x - CENTER) @ ROTATION + CENTER


SHAPES = {
    "cube": dict(points=cube_points,
                 inside=lambda x: _box_sdf(x, 0.0, 1.0) < 0.0,
                 inner_error=lambda x, l: np.abs(_box_sdf(x, l, 1.0 - l))),
    # The cube turned by a fixed rotation about its centre: with l a multiple of
    # h, the axis-aligned cube's faces and edges fall on grid nodes, where
    # phi0 = 0 and the edge-stopping function (4) vanishes, so they never move.
    "rotated cube": dict(points=lambda spacing: (cube_points(spacing) - CENTER) @ ROTATION.T + CENTER,
                         inside=lambda x: _box_sdf(_unrotate(x), 0.0, 1.0) < 0.0,
                         inner_error=lambda x, l: np.abs(_box_sdf(_unrotate(x), l, 1.0 - l))),
    "sphere": dict(points=sphere_points,
                   inside=lambda x: np.linalg.norm(x - CENTER, axis=1) < 0.5,
                   inner_error=lambda x, l: np.abs(np.linalg.norm(x - CENTER, axis=1) - (0.5 - l))),
    "cylinder": dict(points=cylinder_points,
                     inside=lambda x: _cylinder_sdf(x, 0.5, 0.0, 1.0) < 0.0,
                     inner_error=lambda x, l: np.abs(_cylinder_sdf(x, 0.5 - l, l, 1.0 - l))),
}

# The paper's Table 1: (maximum error, average error) of the inner sheet, l = 0.1.
PAPER_TABLE1 = {
    ("cube", 0.01): (5.241e-2, 9.517e-3),
    ("cube", 0.005): (4.054e-2, 2.456e-3),
    ("rotated cube", 0.01): (5.241e-2, 9.517e-3),
    ("rotated cube", 0.005): (4.054e-2, 2.456e-3),
    ("sphere", 0.01): (1.307e-3, 9.938e-4),
    ("sphere", 0.005): (3.723e-4, 2.173e-4),
    ("cylinder", 0.01): (9.346e-4, 6.460e-4),
    ("cylinder", 0.005): (3.155e-4, 1.527e-4),
}


def inner_sheet_errors(shape, surface_points, offset):
    """Distances from the inner sheet's vertices to the exact inner offset
    surface: (max, mean, vertices) over the whole sheet, and for the cylinder
    also over its side away from the rims (|z - 0.5| < 0.3), where the exact
    surface is smooth."""
    s = SHAPES[shape]
    inner = surface_points[s["inside"](surface_points)]
    e = s["inner_error"](inner, offset)
    result = dict(max=float(e.max()), mean=float(e.mean()), vertices=len(inner))
    if shape == "cylinder":
        side = np.abs(inner[:, 2] - 0.5) < 0.3
        result.update(side_max=float(e[side].max()), side_mean=float(e[side].mean()))
    return result
