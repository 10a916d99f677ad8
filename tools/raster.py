"""A z-buffered triangle rasteriser in numpy, for the report's pictures of a formed fabric over
its bodies: every pixel shows the nearest triangle, which a painter's sort (matplotlib's 3D
axes) gets wrong where fabric lies on a body's large faces.

Orthographic camera looking down at the scene from elevation and azimuth angles (degrees, as
matplotlib's view_init). All (triangle, pixel) pairs of the triangles' bounding boxes are
tested at once in chunks, and the nearest inside pair wins each pixel.
"""
import math

import numpy as np

CHUNK_PAIRS = 4_000_000  # (triangle, pixel) pairs tested at once: bounds the memory to ~0.5 GB


def camera(elevation_deg: float, azimuth_deg: float) -> tuple:
    """(right, up, towards_viewer) unit vectors of an orthographic view."""
    e, a = math.radians(elevation_deg), math.radians(azimuth_deg)
    towards = np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])
    right = np.cross([0.0, 0.0, 1.0], towards)
    right /= np.linalg.norm(right)
    return right, np.cross(towards, right), towards


class Frame:
    """Where the scene's points land in an image of width × height pixels, with a margin."""

    def __init__(self, points: np.ndarray, view: tuple, width: int, margin: float = 0.04):
        self.right, self.up, self.towards = view
        u, v = points @ self.right, points @ self.up
        self.u0, self.v1 = u.min(), v.max()
        span_u, span_v = max(u.max() - self.u0, 1e-12), max(self.v1 - v.min(), 1e-12)
        self.scale = width * (1 - 2 * margin) / span_u
        self.offset = width * margin
        self.width = width
        self.height = int(math.ceil(span_v * self.scale + 2 * self.offset))

    def project(self, points: np.ndarray) -> np.ndarray:
        """(x, y) pixel coordinates and depth (larger is nearer) of each point."""
        x = (points @ self.right - self.u0) * self.scale + self.offset
        y = (self.v1 - points @ self.up) * self.scale + self.offset
        return np.stack([x, y, points @ self.towards], axis=-1)


def rasterise(frame: Frame, triangles: np.ndarray, nearer_by=None) -> tuple:
    """For each pixel, the nearest triangle (-1 for none) and its barycentric weights.
    `triangles` is (n, 3, 3): corners in scene coordinates; `nearer_by` (n,), optional, counts
    a triangle that much nearer the viewer than it is (a cloth resting on a body shows)."""
    p = frame.project(triangles.reshape(-1, 3)).reshape(-1, 3, 3)
    if nearer_by is not None:
        p[:, :, 2] += np.asarray(nearer_by)[:, None]
    h, w = frame.height, frame.width
    depth = np.full(h * w, -np.inf)
    owner = np.full(h * w, -1, dtype=np.int64)
    weights = np.zeros((h * w, 3))
    x0 = np.clip(np.floor(p[:, :, 0].min(1)).astype(np.int64), 0, w - 1)
    x1 = np.clip(np.ceil(p[:, :, 0].max(1)).astype(np.int64), 0, w - 1)
    y0 = np.clip(np.floor(p[:, :, 1].min(1)).astype(np.int64), 0, h - 1)
    y1 = np.clip(np.ceil(p[:, :, 1].max(1)).astype(np.int64), 0, h - 1)
    counts = (x1 - x0 + 1) * (y1 - y0 + 1)
    start = 0
    while start < len(p):
        stop = start + max(1, int(np.searchsorted(np.cumsum(counts[start:]), CHUNK_PAIRS)))
        _draw(p, start, min(stop, len(p)), (x0, x1, y0, y1, counts), w, depth, owner, weights)
        start = stop
    return owner.reshape(h, w), weights.reshape(h, w, 3)


def _draw(p, start, stop, boxes, w, depth, owner, weights):
    x0, x1, y0, y1, counts = (b[start:stop] for b in boxes)
    tri = np.repeat(np.arange(start, stop), counts)
    local = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    box_w = np.repeat(x1 - x0 + 1, counts)
    px = np.repeat(x0, counts) + local % box_w
    py = np.repeat(y0, counts) + local // box_w
    a, b, c = p[tri, 0], p[tri, 1], p[tri, 2]
    cx, cy = px + 0.5, py + 0.5
    area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])
    ok = np.abs(area) > 1e-12
    area = np.where(ok, area, 1.0)
    wa = ((b[:, 0] - cx) * (c[:, 1] - cy) - (c[:, 0] - cx) * (b[:, 1] - cy)) / area
    wb = ((c[:, 0] - cx) * (a[:, 1] - cy) - (a[:, 0] - cx) * (c[:, 1] - cy)) / area
    wc = 1.0 - wa - wb
    inside = ok & (wa >= 0) & (wb >= 0) & (wc >= 0)
    z = wa * a[:, 2] + wb * b[:, 2] + wc * c[:, 2]
    pixel = (py * w + px)[inside]
    z, tri = z[inside], tri[inside]
    bary = np.stack([wa, wb, wc], axis=1)[inside]
    # Nearest first, then the first of each pixel is its winner in this chunk.
    order = np.lexsort((-z, pixel))
    pixel, z, tri, bary = pixel[order], z[order], tri[order], bary[order]
    first = np.ones(len(pixel), dtype=bool)
    first[1:] = pixel[1:] != pixel[:-1]
    pixel, z, tri, bary = pixel[first], z[first], tri[first], bary[first]
    nearer = z > depth[pixel]
    pixel = pixel[nearer]
    depth[pixel] = z[nearer]
    owner[pixel] = tri[nearer]
    weights[pixel] = bary[nearer]


def lambert(triangles: np.ndarray, towards_light: np.ndarray) -> np.ndarray:
    """Diffuse shading per triangle in [0.35, 0.9], two-sided (a cloth and an open body have
    no outside to trust)."""
    normal = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    length = np.maximum(np.linalg.norm(normal, axis=1), 1e-300)
    return 0.35 + 0.55 * np.abs(normal @ towards_light) / length
