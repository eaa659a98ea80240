package lt.spindulys.adaptive;

import java.util.Arrays;
import java.util.Objects;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.math.Placement;

/**
 * View-dependent tessellation rates: any integer number of segments per control edge, not a
 * power of two. A control edge whose projection is P pixels long gets ceil(P / target) segments,
 * at least 1 and at most a maximum (at most {@link #MAX_RATE}). The projected length is the one
 * {@link EdgeLevels} computes (the same conservative footprint from the edge's two end points, the
 * same bound over the shutter for a moving object, the same off-screen coarsening), so the two
 * faces sharing an edge see the same rate (design note, pitfall 1), and where a level l is
 * unclamped the rate is at most 2^l: rates never refine more than {@code levels edge} does.
 * Stateless.
 *
 * <p>A face's grid takes its resolution from its edges' rates ({@link GridPattern},
 * {@link FacePattern}): a face 68 pixels long and 19 wide gets 68 x 19 quads where the
 * power-of-two level gives 128 x 128.
 */
public final class EdgeRates {
    /**
     * The largest rate: segments per edge, and so grid quads per face side (Embree's clamp). A
     * face at this rate on all sides has 4096 x 4096 quads; callers cap the total further (the
     * patch cache's per-entry limit, design note pitfall 7).
     */
    public static final int MAX_RATE = 4096;

    private EdgeRates() {}

    /**
     * Per control edge, the number of segments (1..maxRate) that brings its projected length to
     * at most {@code targetPixels}.
     *
     * @param view what the camera sees
     * @param positions object-space control points, x, y, z each
     * @param edgeVertices two vertex indices per edge
     * @param placement object to world over the shutter (for a moving object the largest rate
     *        over the shutter, as {@link EdgeLevels} bounds it)
     * @param targetPixels the wanted segment length in pixels, positive and finite
     * @param maxRate the largest rate returned, 1 to {@link #MAX_RATE}
     * @param offscreenScale divisor of lengths outside the view, at least 1
     * @return one rate per edge
     * @throws IllegalArgumentException on a bad argument (named in the message)
     */
    public static int[] perEdge(ViewFootprint view, double[] positions, int[] edgeVertices, Placement placement,
                                double targetPixels, int maxRate, double offscreenScale) {
        Objects.requireNonNull(edgeVertices, "edgeVertices");
        HeapBudget.require(4L * (edgeVertices.length / 2), "the rates of " + edgeVertices.length / 2 + " edges");
        int[] rates = new int[edgeVertices.length / 2];
        Arrays.fill(rates, 1);
        perEdgeMax(view, positions, edgeVertices, placement, targetPixels, maxRate, offscreenScale, rates);
        return rates;
    }

    /**
     * Like {@link #perEdge}, but raises {@code ratesInOut} in place to each edge's rate where that
     * is higher, so that a surface placed several times (instances) gets, per edge, the largest
     * rate any placement needs: call it once per placement on the same array (filled with 1
     * first).
     *
     * @param view what the camera sees
     * @param positions object-space control points, x, y, z each
     * @param edgeVertices two vertex indices per edge
     * @param placement object to world over the shutter
     * @param targetPixels the wanted segment length in pixels, positive and finite
     * @param maxRate the largest rate computed, 1 to {@link #MAX_RATE} (entries already above it stay)
     * @param offscreenScale divisor of lengths outside the view, at least 1
     * @param ratesInOut one rate per edge, raised where needed
     * @throws IllegalArgumentException on a bad argument (named in the message)
     */
    public static void perEdgeMax(ViewFootprint view, double[] positions, int[] edgeVertices, Placement placement,
                                  double targetPixels, int maxRate, double offscreenScale, int[] ratesInOut) {
        checkTarget(targetPixels, maxRate);
        EdgeLevels.raise(view, positions, edgeVertices, placement, pixels -> rateFor(pixels, targetPixels, maxRate),
                maxRate, offscreenScale, true, ratesInOut, "rates");
    }

    /**
     * The rate for a projected length: ceil(pixels / target) clamped to 1..maxRate (a length of
     * exactly k targets needs k segments). A length of 0 or less needs 1; an infinite or unknown
     * (NaN) one gets maxRate, since a finer rate is only slower, never wrong, and maxRate bounds
     * the cost.
     *
     * @param pixels the projected length in pixels
     * @param targetPixels the wanted segment length in pixels, positive and finite
     * @param maxRate the largest rate returned, 1 to {@link #MAX_RATE}
     * @return the rate
     * @throws IllegalArgumentException if the target is not positive and finite or maxRate is out of range
     */
    public static int rateFor(double pixels, double targetPixels, int maxRate) {
        checkTarget(targetPixels, maxRate);
        if (Double.isNaN(pixels)) return maxRate;
        double ratio = pixels / targetPixels;
        if (!(ratio > 1)) return 1;
        if (!(ratio < maxRate)) return maxRate;
        return (int) Math.ceil(ratio);
    }

    /**
     * The power-of-two rate that a level stands for (2^level segments per edge), for comparing
     * the two: a level l's face grid has 2^l x 2^l quads.
     *
     * @param level a level, 0 to 30
     * @return 2^level
     */
    public static int ofLevel(int level) {
        if (level < 0 || level > 30) throw new IllegalArgumentException("level must be 0 to 30, found " + level);
        return 1 << level;
    }

    /**
     * Rounds the rates of every edge of a non-quad face up to even, in place, as the
     * quad-sub-face tessellation of an n-gon needs ({@link FacePattern#polygon}: each sub-face
     * edge is half a base edge). The quads next to the n-gon read the same array, so they see the
     * same even rate on the shared edge. Not for Loop meshes, whose triangles are not split.
     *
     * @param faceSizes corners per face
     * @param faceEdges the control edge of each face's corner k (from corner k to k + 1), face by face
     * @param ratesInOut one rate per control edge, each 1 to {@link #MAX_RATE} (an even maximum, so
     *        rounding up stays within it)
     * @throws IllegalArgumentException if the arrays disagree or a rate is out of range
     */
    public static void evenAroundPolygons(int[] faceSizes, int[] faceEdges, int[] ratesInOut) {
        Objects.requireNonNull(faceSizes, "faceSizes");
        Objects.requireNonNull(faceEdges, "faceEdges");
        Objects.requireNonNull(ratesInOut, "ratesInOut");
        long corners = 0;
        for (int n : faceSizes) {
            if (n < 3) throw new IllegalArgumentException("a face has " + n + " corners; at least 3 are needed");
            corners += n;
        }
        if (corners != faceEdges.length) throw new IllegalArgumentException("faces have " + corners + " corners but " + faceEdges.length + " edges are given");
        for (int r : ratesInOut) if (r < 1 || r > MAX_RATE) throw new IllegalArgumentException("rate " + r + " is not 1 to " + MAX_RATE);
        for (int f = 0, c = 0; f < faceSizes.length; c += faceSizes[f], f++) {
            if (faceSizes[f] == 4) continue;
            for (int k = 0; k < faceSizes[f]; k++) {
                int e = faceEdges[c + k];
                if (e < 0 || e >= ratesInOut.length) throw new IllegalArgumentException("face " + f + " names edge " + e + ", but there are " + ratesInOut.length);
                ratesInOut[e] += ratesInOut[e] & 1;
            }
        }
    }

    private static void checkTarget(double targetPixels, int maxRate) {
        if (!(targetPixels > 0 && targetPixels < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("target edge length must be a positive number of pixels, found " + targetPixels);
        }
        if (maxRate < 1 || maxRate > MAX_RATE) throw new IllegalArgumentException("maximum rate must be 1 to " + MAX_RATE + ", found " + maxRate);
    }
}
