package lt.spindulys.adaptive;

import java.util.Objects;
import java.util.function.DoubleToIntFunction;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;

/**
 * View-dependent subdivision levels: each refinement step of every scheme (Catmull-Clark, Loop,
 * bilinear) halves the edges, so a control edge whose projection is P pixels long needs
 * ceil(log2(P / target)) steps to reach {@code target} pixels. A level is computed per control
 * edge from that edge's two end points only, so the two faces sharing an edge always see the same
 * level (design note, pitfall 1), clamped to a maximum and coarsened off screen (pitfall 8).
 * Stateless.
 *
 * <p><b>Moving objects.</b> The placement is evaluated at {@link #INTERVALS} + 1 times evenly spread
 * over the shutter, its ends included. Between two samples each end of an edge stays within the
 * distance d it moves from one sample to the next (the chord: exact for a translation, a scale, or
 * a rotation of at most 180 degrees between samples, that is 1800 degrees over the shutter; for
 * motions combined in one placement a close approximation, off by the path's second-order bend,
 * which Motion's sweep pads for boxes and this bound does not), and because the placement is
 * affine every point of the edge does too. So for each interval
 * the edge is bounded as a segment no longer than min(L0, L1) plus the change of the vector b - a
 * (which the linear part alone moves, so the same argument holds for it), whose distance from the
 * eye is at least either sample's distance minus max(dA, dB), inside a frustum widened by that
 * much: no time in between can hide a closer, longer or visible position. The bound is loose where
 * an edge moves far compared with its distance from the eye; where it costs a level over both
 * sampled ends, the interval is bounded again in {@link #STEPS} finer steps (each as rigorous), so
 * the extra evaluations go only to the few edges that sweep close past the camera.
 *
 * <p>{@link EdgeRates} turns the same projected lengths into integer segment counts.
 */
public final class EdgeLevels {
    /** Intervals between the placement's samples over the shutter of a moving object: 9 times inside plus the open and close times. */
    static final int INTERVALS = 10;
    /** Finer steps in each interval, taken only where the coarse bound costs a level (see the class comment). */
    static final int STEPS = 8;

    private EdgeLevels() {}

    /**
     * Per control edge, the level (0..maxLevel) that brings its projected length to at most
     * {@code targetPixels}.
     *
     * @param view what the camera sees
     * @param positions object-space control points, x, y, z each
     * @param edgeVertices two vertex indices per edge
     * @param placement object to world over the shutter (for a moving object the largest level
     *        over the shutter: see the class comment)
     * @param targetPixels the wanted edge length in pixels, positive and finite
     * @param maxLevel the largest level returned, at least 0
     * @param offscreenScale divisor of lengths outside the view, at least 1
     * @return one level per edge
     * @throws IllegalArgumentException on a bad argument (named in the message)
     */
    public static int[] perEdge(ViewFootprint view, double[] positions, int[] edgeVertices, Placement placement,
                                double targetPixels, int maxLevel, double offscreenScale) {
        Objects.requireNonNull(edgeVertices, "edgeVertices");
        HeapBudget.require(4L * (edgeVertices.length / 2), "the levels of " + edgeVertices.length / 2 + " edges");
        int[] levels = new int[edgeVertices.length / 2];
        perEdgeMax(view, positions, edgeVertices, placement, targetPixels, maxLevel, offscreenScale, levels);
        return levels;
    }

    /**
     * Like {@link #perEdge}, but raises {@code levelsInOut} in place to each edge's level where
     * that is higher, so that a surface placed several times (instances) gets, per edge, the
     * largest level any placement needs: call it once per placement on the same array.
     *
     * @param view what the camera sees
     * @param positions object-space control points, x, y, z each
     * @param edgeVertices two vertex indices per edge
     * @param placement object to world over the shutter
     * @param targetPixels the wanted edge length in pixels, positive and finite
     * @param maxLevel the largest level computed, at least 0 (entries already above it stay)
     * @param offscreenScale divisor of lengths outside the view, at least 1
     * @param levelsInOut one level per edge, raised where needed
     * @throws IllegalArgumentException on a bad argument (named in the message)
     */
    public static void perEdgeMax(ViewFootprint view, double[] positions, int[] edgeVertices, Placement placement,
                                  double targetPixels, int maxLevel, double offscreenScale, int[] levelsInOut) {
        checkTarget(targetPixels, maxLevel);
        raise(view, positions, edgeVertices, placement, pixels -> levelFor(pixels, targetPixels, maxLevel), maxLevel, offscreenScale, false, levelsInOut, "levels");
    }

    /**
     * The common core of levels and rates ({@link EdgeRates}): per edge, the projected length in
     * pixels (bounded over the shutter as the class comment says), turned into an integer by
     * {@code quantize} (non-decreasing in the length), raising {@code valuesInOut} where that is
     * higher. Edges already at {@code max} or above are skipped; {@code noun} names the array in messages.
     * With {@code subtended}, a still edge is measured by the angle it subtends
     * ({@link ViewFootprint#subtendedPixels}) rather than bounded with foreshortening ignored.
     */
    static void raise(ViewFootprint view, double[] positions, int[] edgeVertices, Placement placement,
                      DoubleToIntFunction quantize, int max, double offscreenScale, boolean subtended, int[] valuesInOut, String noun) {
        Objects.requireNonNull(view, "view");
        Objects.requireNonNull(positions, "positions");
        Objects.requireNonNull(edgeVertices, "edgeVertices");
        Objects.requireNonNull(placement, "placement");
        Objects.requireNonNull(valuesInOut, "valuesInOut");
        ViewFootprint.checkOffscreenScale(offscreenScale);
        if (positions.length % 3 != 0) throw new IllegalArgumentException("positions hold x, y, z per point, but their count " + positions.length + " is not a multiple of 3");
        if (edgeVertices.length % 2 != 0) throw new IllegalArgumentException("edges hold 2 vertices each, but their count " + edgeVertices.length + " is odd");
        int edges = edgeVertices.length / 2, points = positions.length / 3;
        if (valuesInOut.length != edges) throw new IllegalArgumentException(noun + " array has " + valuesInOut.length + " entries for " + edges + " edges");
        for (int e = 0; e < edges; e++) {
            for (int k = 0; k < 2; k++) {
                int v = edgeVertices[2 * e + k];
                if (v < 0 || v >= points) throw new IllegalArgumentException("edge " + e + " names vertex " + v + ", but there are " + points + " control points");
                if (!(Double.isFinite(positions[3 * v]) && Double.isFinite(positions[3 * v + 1]) && Double.isFinite(positions[3 * v + 2]))) {
                    throw new IllegalArgumentException("control point " + v + " is not finite");
                }
            }
        }
        double[] m = matrices(placement);
        double[] a0 = new double[3], b0 = new double[3], a1 = new double[3], b1 = new double[3];
        for (int e = 0; e < edges; e++) {
            if (valuesInOut[e] >= max) continue;
            int va = 3 * edgeVertices[2 * e], vb = 3 * edgeVertices[2 * e + 1];
            double pixels;
            if (m.length == 12) {
                apply(m, 0, positions, va, a0);
                apply(m, 0, positions, vb, b0);
                pixels = subtended ? view.subtendedPixels(a0[0], a0[1], a0[2], b0[0], b0[1], b0[2], offscreenScale)
                        : view.pixels(a0[0], a0[1], a0[2], b0[0], b0[1], b0[2], dist(a0, b0), 0, offscreenScale);
            } else {
                pixels = 0;
                apply(m, 0, positions, va, a0);
                apply(m, 0, positions, vb, b0);
                double atStart = view.pixels(a0[0], a0[1], a0[2], b0[0], b0[1], b0[2], dist(a0, b0), 0, offscreenScale);
                for (int c = 0; c < INTERVALS && !(pixels == Double.POSITIVE_INFINITY); c++) {
                    int k0 = c * STEPS, k1 = k0 + STEPS;
                    apply(m, k0, positions, va, a0);
                    apply(m, k0, positions, vb, b0);
                    apply(m, k1, positions, va, a1);
                    apply(m, k1, positions, vb, b1);
                    double atEnd = view.pixels(a1[0], a1[1], a1[2], b1[0], b1[1], b1[2], dist(a1, b1), 0, offscreenScale);
                    double p = between(view, a0, b0, a1, b1, offscreenScale);
                    // Where the padding costs a level over both sampled ends, the finer steps
                    // (each as rigorous) may win it back.
                    if (quantize.applyAsInt(p) > quantize.applyAsInt(Math.max(atStart, atEnd))) {
                        double fine = 0;
                        for (int k = k0; k < k1 && fine < p; k++) {
                            apply(m, k, positions, va, a0);
                            apply(m, k, positions, vb, b0);
                            apply(m, k + 1, positions, va, a1);
                            apply(m, k + 1, positions, vb, b1);
                            double q = between(view, a0, b0, a1, b1, offscreenScale);
                            if (!(q <= fine)) fine = q;
                        }
                        if (!(fine >= p)) p = fine;
                    }
                    if (p > pixels || Double.isNaN(p)) pixels = p;
                    atStart = atEnd;
                }
            }
            int value = quantize.applyAsInt(pixels);
            if (value > valuesInOut[e]) valuesInOut[e] = value;
        }
    }

    /** A bound on the pixels of the edge at every time between two samples (see the class comment). */
    private static double between(ViewFootprint view, double[] a0, double[] b0, double[] a1, double[] b1, double offscreenScale) {
        double da = dist(a0, a1), db = dist(b0, b1);
        // b - a is mapped by the linear part alone, so it moves on the same kind of path:
        // its length in between is within the chord of its own change (0 for a translation).
        double dvx = (b1[0] - a1[0]) - (b0[0] - a0[0]), dvy = (b1[1] - a1[1]) - (b0[1] - a0[1]), dvz = (b1[2] - a1[2]) - (b0[2] - a0[2]);
        double length = Math.min(dist(a0, b0), dist(a1, b1)) + Math.sqrt(dvx * dvx + dvy * dvy + dvz * dvz);
        double pad = Math.max(da, db);
        // Each sample's segment bounds every one in between; the smaller bound is the better.
        return Math.min(view.pixels(a0[0], a0[1], a0[2], b0[0], b0[1], b0[2], length, pad, offscreenScale),
                view.pixels(a1[0], a1[1], a1[2], b1[0], b1[1], b1[2], length, pad, offscreenScale));
    }

    /**
     * The thesis's section 6.1: one level for the whole object, from its longest projected control
     * edge (the largest of the per-edge levels, as the level grows with the length).
     *
     * @param view what the camera sees
     * @param positions object-space control points, x, y, z each
     * @param edgeVertices two vertex indices per edge
     * @param placement object to world over the shutter
     * @param targetPixels the wanted edge length in pixels, positive and finite
     * @param maxLevel the largest level returned, at least 0
     * @param offscreenScale divisor of lengths outside the view, at least 1
     * @return the level, 0 for an object without edges
     */
    public static int perObject(ViewFootprint view, double[] positions, int[] edgeVertices, Placement placement,
                                double targetPixels, int maxLevel, double offscreenScale) {
        int level = 0;
        for (int l : perEdge(view, positions, edgeVertices, placement, targetPixels, maxLevel, offscreenScale)) level = Math.max(level, l);
        return level;
    }

    /**
     * The level for a projected length: ceil(log2(pixels / target)) clamped to 0..maxLevel,
     * computed exactly (a length of exactly 2^k targets needs k steps, not k + 1). A length of 0
     * or less needs none; an infinite or unknown (NaN) one gets maxLevel, since a finer level is
     * only slower, never wrong, and maxLevel bounds the cost.
     *
     * @param pixels the projected length in pixels
     * @param targetPixels the wanted length in pixels, positive and finite
     * @param maxLevel the largest level returned, at least 0
     * @return the level
     * @throws IllegalArgumentException if the target is not positive and finite or maxLevel is negative
     */
    public static int levelFor(double pixels, double targetPixels, int maxLevel) {
        checkTarget(targetPixels, maxLevel);
        if (Double.isNaN(pixels)) return maxLevel;
        double ratio = pixels / targetPixels;
        if (!(ratio > 1)) return 0;
        if (ratio == Double.POSITIVE_INFINITY) return maxLevel;
        int floor = Math.getExponent(ratio); // ratio > 1, so a normal number: its exponent is floor(log2)
        int level = Math.scalb(1.0, floor) == ratio ? floor : floor + 1;
        return Math.min(level, maxLevel);
    }

    private static void checkTarget(double targetPixels, int maxLevel) {
        if (!(targetPixels > 0 && targetPixels < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("target edge length must be a positive number of pixels, found " + targetPixels);
        }
        if (maxLevel < 0) throw new IllegalArgumentException("maximum level must be at least 0, found " + maxLevel);
    }

    /** Row-major 3x4 object-to-world matrices, one per time sample (one for a static placement). */
    private static double[] matrices(Placement placement) {
        if (placement.isStatic() || placement.open() == placement.close()) {
            return matrix(placement.isStatic() ? placement.staticTransform() : placement.at(placement.open()));
        }
        int samples = INTERVALS * STEPS + 1;
        double[] m = new double[12 * samples];
        double open = placement.open(), close = placement.close();
        for (int k = 0; k < samples; k++) {
            double time = k == samples - 1 ? close : open + (close - open) * k / (samples - 1);
            System.arraycopy(matrix(placement.at(time)), 0, m, 12 * k, 12);
        }
        return m;
    }

    /** The matrix of a transform, read back through its public maps (exactly: each entry is a product by 1 plus zeros). */
    private static double[] matrix(Transform t) {
        Vec3 o = t.point(Vec3.ZERO), x = t.vector(Vec3.X), y = t.vector(Vec3.Y), z = t.vector(Vec3.Z);
        return new double[] {x.x(), y.x(), z.x(), o.x(), x.y(), y.y(), z.y(), o.y(), x.z(), y.z(), z.z(), o.z()};
    }

    private static void apply(double[] m, int k, double[] p, int i, double[] out) {
        int o = 12 * k;
        double x = p[i], y = p[i + 1], z = p[i + 2];
        out[0] = m[o] * x + m[o + 1] * y + m[o + 2] * z + m[o + 3];
        out[1] = m[o + 4] * x + m[o + 5] * y + m[o + 6] * z + m[o + 7];
        out[2] = m[o + 8] * x + m[o + 9] * y + m[o + 10] * z + m[o + 11];
    }

    private static double dist(double[] a, double[] b) {
        double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
