"""The coding-1 syntax of a polygon stroke (SPEC.md 7.4 step 5, format 1.2): the vertex count,
the grid, the first vertex, the lattice shift and the vertices in one of three modes."""
from .errors import fail
from .range_coder import Context, SInt, Tree, UInt
from .strokes import check_coord

ONE = 1 << 30  # 1.0 in the conic mode's Q30 unit vectors


def decode_grid(rc, same, tree, prev, bad):
    """A polygon's or a curve's grid (SPEC.md 7.4): `prev` when flag(same) is 0, else tree(5),
    which must differ from `prev` and be 0 or 2..16 (`bad(grid)` otherwise)."""
    if not rc.flag(same):
        return prev
    grid = rc.tree(tree)
    if grid == prev or grid == 1 or grid > 16:
        bad(grid)
    return grid


class PolygonContexts:
    def __init__(self):
        self.points = UInt()
        self.same_aa, self.second, self.conic = Context(), Context(), Context()
        self.aa = Tree(5)
        self.shift = Tree(3)
        self.dx, self.dy = [SInt(), SInt()], [SInt(), SInt()]
        self.conic_same = Context()
        self.conic_c = UInt()
        self.conic_s = SInt()
        self.conic_shift = Tree(3)
        self.conic_m = [SInt() for _ in range(4)]
        self.conic_rx, self.conic_ry = SInt(), SInt()
        self.prev_aa = 0
        self.prev_rot = (0, 0)


def decode_polygon(ss):
    """Decodes one polygon from the stroke stream `ss`; returns (grid, vertices)."""
    if ss.polygon_state is None:
        ss.polygon_state = PolygonContexts()
    pc, rc = ss.polygon_state, ss.rc
    n = 3 + rc.uint(pc.points)
    if n > 1 << 16:
        fail("LimitExceeded", f"{ss.what}: polygon of {n} vertices")
    grid = pc.prev_aa = decode_grid(rc, pc.same_aa, pc.aa, pc.prev_aa, lambda g: ss.fail(f"polygon grid {g}"))
    x0, y0 = ss.position(3, 0), ss.position(3, 1)
    s = rc.tree(pc.shift)
    if s > 4:
        ss.fail(f"polygon shift {s}")
    if rc.flag(pc.conic):
        steps = conic_steps(ss, pc, n, s)
    else:
        m = rc.flag(pc.second)
        steps, e, f = [], 0, 0
        for _ in range(n - 1):
            pred_e, pred_f = (e, f) if m == 1 else (0, 0)
            e = pred_e + rc.sint(pc.dx[m])
            f = pred_f + rc.sint(pc.dy[m])
            steps.append((e, f))
        # the differences add up to offsets from P_0
        offsets, ox, oy = [], 0, 0
        for e, f in steps:
            ox, oy = ox + e, oy + f
            offsets.append((ox, oy))
        steps = offsets
    vertices = [[x0, y0]]
    for e, f in steps:  # offsets from P_0 in lattice steps of 2^s
        x, y = x0 + (e << s), y0 + (f << s)
        check_coord(x, ss.what)
        check_coord(y, ss.what)
        vertices.append([x, y])
    if s < 4 and all(e % 2 == 0 and f % 2 == 0 for e, f in steps):
        ss.fail("polygon shift is not the largest")
    return grid, vertices


def conic_steps(ss, pc, n, s):
    """Mode 2: the offsets e_i, f_i of vertices 1 .. n-1 from P_0, in lattice steps."""
    rc = ss.rc
    Rc, Rs = pc.prev_rot
    if rc.flag(pc.conic_same):
        Rc = ONE - rc.uint(pc.conic_c)
        Rs = rc.sint(pc.conic_s)
        if abs(Rc) > ONE or abs(Rs) > ONE:
            ss.fail("conic rotation out of range")
        if (Rc, Rs) == pc.prev_rot:
            ss.fail("conic rotation equal to the previous one coded in full")
    pc.prev_rot = (Rc, Rs)
    t = rc.tree(pc.conic_shift)
    if t > 4:
        ss.fail(f"conic matrix shift {t}")
    m = []
    for k in range(4):
        v = rc.sint(pc.conic_m[k])
        if abs(v << t) > 1 << 26:
            ss.fail("conic matrix entry outside +-2^26")
        m.append(v)
    if t < 4 and all(v % 2 == 0 for v in m):
        ss.fail("conic matrix shift is not the largest")
    ma, mb, mc, md = (v << t for v in m)
    u, v = ONE, 0
    k = 30 + s
    steps = []
    for _ in range(n - 1):
        u, v = (min(max((Rc * u - Rs * v + (1 << 29)) >> 30, -(1 << 31)), 1 << 31),
                min(max((Rs * u + Rc * v + (1 << 29)) >> 30, -(1 << 31)), 1 << 31))
        du, dv = u - ONE, v
        pe = (ma * du + mb * dv + (1 << (k - 1))) >> k
        pf = (mc * du + md * dv + (1 << (k - 1))) >> k
        steps.append((pe + rc.sint(pc.conic_rx), pf + rc.sint(pc.conic_ry)))
    return steps
