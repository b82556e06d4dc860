#!/usr/bin/env python3
"""Write the seed corpora of the fuzz targets to tests/fuzz/corpus/<target>/ (a handful of small,
meaningful inputs each; the fuzzer mutates them). Run again after changing a decoder in
FuzzInput.h, FuzzShapes.h or a target, and commit the files; regression inputs found by the
fuzzer (crash-*) are kept next to these and are not written here.

The solver and world targets read bytes front to back (FuzzInput.h): a number is a selector byte
(below 224: ordinary) and two bytes of a 16-bit fraction of its range; Int, Bool and Byte take one
byte. The helpers below spell those out."""
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def frac(x):
    """Two bytes for a fraction x in [0, 1] of an ordinary range."""
    u = round(max(0.0, min(1.0, x)) * 65535)
    return bytes([u >> 8, u & 255])


def num(x):
    """An ordinary Number or Positive: selector 0, then the fraction."""
    return bytes([0]) + frac(x)


def extreme(k):
    """The extreme value number k of FuzzInput's table (e.g. 20: +inf, 22: NaN, 16: 1e300)."""
    return bytes([224 + k])


def byte(v):
    return bytes([v])


# Shapes (FuzzShapes.h DecodeShape): kind byte, then its numbers. Sizes are log-uniform in
# [0.05, 20]: fraction 0.5 is 1, 0.73 about 3.
def circle(r_frac):
    return byte(0) + num(r_frac)


def ellipse(a, b):
    return byte(1) + num(a) + num(b)


def superellipse_int(a, b, n, m):
    return byte(2) + num(a) + num(b) + byte(n - 1) + byte(m - 1)


def superellipse_real(a, b, n_frac, m_frac):
    return byte(3) + num(a) + num(b) + num(n_frac) + num(m_frac)


def heart(size, squared=True):
    return byte(5) + num(size) + byte(1 if squared else 0)


def user(s, e, k, p, flags):
    """Star shape (|x|/(s(1 + e cos(k t + phi))))^p, level 1, the flag bytes as given."""
    return (byte(6) + frac(s) + frac(e) + byte(k - 1) + frac(0.5) + byte(p - 1) + num((1.0 - 0.2) / 4.8)
            + bytes(flags))


def pose(x_frac, y_frac, angle_frac):
    """Position (fractions of [-2, 2] times the pair's size) and angle (fraction of [-pi, pi])."""
    return num(x_frac) + num(y_frac) + num(angle_frac)


def write(target, name, data):
    folder = os.path.join(HERE, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def solvers():
    # After the two shapes and their poses: the solver options (a Bool, then iteration cap, grid
    # samples 8 << k and candidates when it is 1), B's held level, the motions (velocities in
    # units of the pair's size per second, spins, tMax), the queries (two points, a fraction, a
    # reach) and the polygon (count, radius, pose); zero bytes past the end.
    def rest(options=byte(0)):
        levels = num(0.3)
        motions = num(0.8) + num(0.5) + num(0.2) + num(0.5) + num(0.5) + num(0.6) + num(0.6)
        queries = num(0.2) + num(0.5) + num(0.9) + num(0.6) + num(0.9) + num(0.5)
        polygon = byte(2) + num(0.5) + pose(0.5, 0.2, 0.5)
        return options + levels + motions + queries + polygon

    apart = pose(0.25, 0.5, 0.5)
    right = pose(0.75, 0.55, 0.6)
    write("solvers", "circles_apart", circle(0.5) + circle(0.73) + apart + right + rest())
    write("solvers", "ellipses_touching", ellipse(0.73, 0.5) + ellipse(0.6, 0.4) + pose(0.4, 0.5, 0.3) + pose(0.6, 0.5, 0.7) + rest())
    write("solvers", "superellipses_6_8", superellipse_int(0.6, 0.7, 6, 8) + superellipse_int(0.6, 0.7, 6, 8) + apart + right + rest())
    write("solvers", "superellipse_real_exponents", superellipse_real(0.6, 0.5, 0.13, 0.37) + ellipse(0.5, 0.4) + apart + right
          + rest(byte(1) + byte(10) + byte(2) + byte(3)))
    write("solvers", "heart_and_ellipse", heart(0.5) + ellipse(0.55, 0.45) + pose(0.45, 0.5, 0.5) + pose(0.55, 0.5, 0.2) + rest())
    write("solvers", "user_star", user(0.5, 0.2, 5, 2, [1, 1, 0, 0, 1, 1, 0]) + circle(0.4) + apart + right + rest())
    write("solvers", "coincident_centres", ellipse(0.7, 0.5) + superellipse_int(0.5, 0.6, 4, 4) + pose(0.5, 0.5, 0.1)
          + pose(0.5, 0.5, 0.9) + rest())
    write("solvers", "infinite_position", circle(0.5) + ellipse(0.6, 0.5) + extreme(20) + num(0.5) + num(0.5) + right + rest())


def world():
    # Gravity, body count, then per body: type, position, angle, velocity, spin, bullet, fixture
    # count and fixtures (density, friction, restitution, sensor byte, kind, shape or sizes).
    def body(kind, x, y, fixtures):
        return (byte(kind) + frac(x) + frac(y) + frac(0.5) + frac(0.5) + frac(0.5) + frac(0.5) + byte(0)
                + byte(len(fixtures) - 1) + b"".join(fixtures))

    def analytic(shape):
        return frac(0.2) + frac(0.5) + frac(0.1) + byte(200) + byte(0) + shape + frac(0.5) + frac(0.5) + frac(0.5) + byte(0)

    def box(hx, hy):
        return frac(0.2) + frac(0.5) + frac(0.0) + byte(200) + byte(4) + frac(0.5) + frac(0.5) + frac(hx) + frac(hy) + frac(0.5)

    def edge():
        return frac(0.0) + frac(0.5) + frac(0.0) + byte(200) + byte(5) + frac(0.0) + frac(0.5) + frac(1.0) + frac(0.5)

    # Between two steps: the operation, a body index byte, the operation's own bytes (FuzzWorld.cpp
    # BetweenSteps), then the time step and the iteration counts (8 velocity, 3 position).
    arguments = {0: 6, 1: 4, 2: 0, 3: 1, 4: 8, 5: 4, 6: 2, 7: 1, 8: 6, 9: 0}

    def step(op):
        return byte(op) + byte(1) + bytes([128] * arguments[op]) + frac(0.5) + byte(7) + byte(2)

    gravity = frac(0.5) + frac(0.25)
    floor = body(0, 0.5, 0.3, [edge()])
    # Sizes in [0.005, 4] log-uniform: fraction 0.8 is about 1.
    steps = byte(39) + b"".join(step(9) for _ in range(40))
    write("world", "ellipse_on_floor", gravity + byte(1) + floor + body(2, 0.5, 0.4, [analytic(ellipse(0.8, 0.7))]) + steps)
    write("world", "stack_of_superellipses", gravity + byte(2) + floor + body(2, 0.5, 0.4, [analytic(superellipse_int(0.8, 0.75, 6, 6))])
          + body(2, 0.5, 0.45, [analytic(superellipse_int(0.8, 0.75, 6, 6))]) + steps)
    write("world", "heart_and_box", gravity + byte(2) + floor + body(2, 0.48, 0.4, [analytic(heart(0.8))])
          + body(2, 0.52, 0.42, [box(0.5, 0.5)]) + steps)
    write("world", "mixed_with_removals", gravity + byte(3) + floor + body(2, 0.5, 0.4, [analytic(circle(0.8)), box(0.4, 0.4)])
          + body(1, 0.45, 0.45, [analytic(user(0.8, 0.1, 3, 2, [0, 1, 1, 1, 1, 1, 0]))])
          + body(2, 0.55, 0.45, [analytic(superellipse_real(0.8, 0.7, 0.2, 0.3))])
          + byte(9) + b"".join(step(op) for op in (4, 5, 6, 0, 1, 7, 8, 2, 3, 9)))
    write("world", "too_small", gravity + byte(0) + body(2, 0.5, 0.5, [analytic(circle(0.0))]) + byte(3))


def contact_tool():
    requests = {
        "circles": '{"id":1,"a":{"type":"circle","r":1},"b":{"type":"circle","r":2,"x":4}}',
        "common_superellipses": '{"id":2,"mode":"common","a":{"type":"superellipse","a":2,"b":4,"n":6,"m":8},'
                                '"b":{"type":"superellipse","a":2,"b":4,"n":6,"m":8,"x":13,"y":9,"angle":-0.52}}',
        "scale_a_heart": '{"id":"h","mode":"scale_a","method":"grid","a":{"type":"heart","alpha":1},'
                         '"b":{"type":"ellipse","a":1,"b":0.5,"x":2.5,"y":1,"angle":0.3}}',
        "newton_ellipses": '{"id":[1,2],"method":"newton","a":{"type":"ellipse","a":2,"b":1},'
                           '"b":{"type":"ellipse","a":1,"b":0.25,"x":2.9,"angle":1.5707963}}',
        "real_exponents": '{"id":null,"mode":"contact","a":{"type":"superellipse","a":1,"b":1,"n":1.5,"m":3.25},'
                          '"b":{"type":"superellipse","a":1,"b":2,"n":1,"m":1,"x":1.5,"y":-0.5}}',
        "bad_field": '{"id":6,"a":{"type":"circle","r":-1},"b":{"type":"circle","r":1}}',
        "malformed": '{"id":7,"a":{"type":"circ',
    }
    for name, text in requests.items():
        write("contact_tool", name, text.encode())


if __name__ == "__main__":
    solvers()
    world()
    contact_tool()
