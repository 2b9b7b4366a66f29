"""Offscreen pictures of primitives with Pillow: a small painter's-algorithm renderer.

Fast enough for an animation of a whole job (a few milliseconds a frame, no
browser, no GPU): every solid becomes flat-shaded polygons (a box its six faces,
a cylinder or a capsule a 10-sided prism), projected through a pinhole camera
and painted far to near; the table first, the trail, frames and labels last.
The camera looks at the arm from the front right, as the web view's first one.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from PIL import Image, ImageDraw, ImageFont

from .._primitives import (
    RGB,
    Axes,
    Box,
    Capsule,
    Cylinder,
    Label,
    Polyline,
    Primitive,
    Sphere,
)
from ._meshes import segment_frame

F64 = NDArray[np.float64]
SIDES = 10  # of a cylinder's or a capsule's prism
LIGHT = np.array([0.35, -0.55, 1.0]) / np.linalg.norm([0.35, -0.55, 1.0])
BACKGROUND: RGB = (255, 255, 255)
AXIS_COLOURS: tuple[RGB, RGB, RGB] = ((220, 40, 40), (40, 170, 40), (40, 70, 220))
SIGNS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=np.float64)
BOX_FACES = ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3))


@dataclass(frozen=True)
class Camera:
    """A pinhole camera at ``eye`` [m] looking at ``target`` [m] (z up), vertical field of
    view ``fov`` [rad], pictures ``width`` x ``height`` [px]."""

    eye: F64
    target: F64
    fov: float = math.radians(50.0)
    width: int = 640
    height: int = 480

    def project(self, points: F64) -> tuple[F64, F64]:
        """Pixels (N, 2) and depths (N,) [m] of world ``points`` (N, 3)."""
        forward = self.target - self.eye
        forward = forward / np.linalg.norm(forward)
        right = np.cross(forward, [0.0, 0.0, 1.0])
        right = right / np.linalg.norm(right)
        up = np.cross(right, forward)
        rel = points - self.eye
        depth = np.maximum(rel @ forward, 1e-6)
        f = (self.height / 2) / math.tan(self.fov / 2)
        u = self.width / 2 + f * (rel @ right) / depth
        v = self.height / 2 - f * (rel @ up) / depth
        return np.stack([u, v], axis=1), depth


def look_from_front_right(centre: F64, reach: float, width: int, height: int) -> Camera:
    """The view's usual camera for an arm of ``reach`` [m] with its base at ``centre``."""
    eye = centre + np.array([1.1 * reach, -1.0 * reach, 0.95 * reach])
    target = centre + np.array([0.3 * reach, 0.0, 0.3 * reach])
    return Camera(eye, target, width=width, height=height)


@dataclass(frozen=True)
class _Face:
    points: F64  # (K, 3)
    colour: RGB
    centre: F64  # of the solid it bounds: faces turned away from the camera are not drawn
    ground: bool = False  # drawn before everything else (the table)


def render(primitives: Iterable[Primitive], camera: Camera, title: str = "") -> Image.Image:
    """A picture of ``primitives`` seen by ``camera``, with ``title`` top left."""
    image = Image.new("RGB", (camera.width, camera.height), BACKGROUND)
    draw = ImageDraw.Draw(image)
    faces: list[_Face] = []
    overlays: list[Primitive] = []
    for prim in primitives:
        if isinstance(prim, Polyline | Label | Axes | Sphere):
            overlays.append(prim)
        else:
            faces += _faces(prim)
    keyed = []
    for face in faces:
        middle = face.points.mean(axis=0)
        if float((middle - face.centre) @ (middle - camera.eye)) > 0:
            continue  # a back face
        pixels, depth = camera.project(face.points)
        normal = np.cross(face.points[1] - face.points[0], face.points[2] - face.points[0])
        flat = abs(normal[2]) > 0.9 * np.linalg.norm(normal)
        key = math.inf if face.ground else float(depth.max() if flat else depth.mean())
        keyed.append((key, pixels, _shade(face.colour, normal)))
    for _, pixels, colour in sorted(keyed, key=lambda k: -k[0]):
        draw.polygon([tuple(p) for p in pixels.tolist()], fill=colour)
    for prim in overlays:
        _overlay(draw, prim, camera)
    if title:
        draw.text((8, 6), title, fill=(20, 20, 20), font=_font(14))
    return image


def _font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    """Pillow's own font at ``size`` [px] (its bitmap font on an old Pillow)."""
    try:
        return ImageFont.load_default(size=size)
    except TypeError:
        return ImageFont.load_default()


def _shade(colour: RGB, normal: F64) -> RGB:
    n = np.linalg.norm(normal)
    light = abs(float(normal @ LIGHT)) / n if n > 0 else 1.0
    k = 0.55 + 0.45 * light
    return (round(colour[0] * k), round(colour[1] * k), round(colour[2] * k))


def _faces(prim: Primitive) -> list[_Face]:
    if isinstance(prim, Box):
        corners = (prim.T[:3, :3] @ (SIGNS * prim.size / 2).T).T + prim.T[:3, 3]
        ground = prim.name == "/table"
        return [_Face(corners[list(f)], prim.color, prim.T[:3, 3], ground) for f in BOX_FACES]
    if isinstance(prim, Cylinder):
        axis = prim.T[:3, 2] * prim.height / 2
        c = prim.T[:3, 3]
        return _prism(c - axis, c + axis, prim.radius, prim.color)
    if isinstance(prim, Capsule):
        return _prism(prim.p0, prim.p1, prim.radius, prim.color)
    return []


def _prism(p0: F64, p1: F64, radius: float, colour: RGB) -> list[_Face]:
    """A ``SIDES``-sided prism of ``radius`` [m] from ``p0`` to ``p1`` [m], ends closed."""
    T, _ = segment_frame(p0, p1)
    x, y = T[:3, 0], T[:3, 1]
    angles = np.linspace(0.0, 2 * math.pi, SIDES, endpoint=False)
    ring = radius * (np.cos(angles)[:, None] * x + np.sin(angles)[:, None] * y)
    a, b, c = p0 + ring, p1 + ring, (p0 + p1) / 2
    faces = [_Face(np.array([a[i], a[(i + 1) % SIDES], b[(i + 1) % SIDES], b[i]]), colour, c) for i in range(SIDES)]  # fmt: skip
    return [*faces, _Face(a[::-1], colour, c), _Face(b, colour, c)]


def _overlay(draw: ImageDraw.ImageDraw, prim: Primitive, camera: Camera) -> None:
    if isinstance(prim, Polyline):
        pixels, _ = camera.project(prim.points)
        draw.line([tuple(p) for p in pixels.tolist()], fill=prim.color, width=max(1, round(prim.width)))  # fmt: skip
    elif isinstance(prim, Sphere):
        (u, v), depth = (a[0] for a in camera.project(prim.center[None, :]))
        r = (camera.height / 2) / math.tan(camera.fov / 2) * prim.radius / float(depth)
        draw.ellipse((u - r, v - r, u + r, v + r), fill=prim.color)
    elif isinstance(prim, Label):
        (u, v), _ = (a[0] for a in camera.project(prim.position[None, :]))
        draw.text((float(u), float(v)), prim.text, fill=prim.color, font=_font(12))
    elif isinstance(prim, Axes):
        ends = prim.T[:3, 3] + prim.length * prim.T[:3, :3].T
        pixels, _ = camera.project(np.vstack([prim.T[:3, 3], ends]))
        for k in range(3):
            draw.line([tuple(pixels[0]), tuple(pixels[k + 1])], fill=AXIS_COLOURS[k], width=2)
