package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.accel.BruteForce;
import lt.spindulys.accel.PrimitiveHit;
import lt.spindulys.accel.PrimitiveSet;
import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.math.Ray;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.SpanBuffer;
import lt.spindulys.trace.TraceContext;

/**
 * The spans of a closed surface of indexed triangles, without a mesh object: a line through
 * vertices shared by four triangles gives four crossings with exactly the same t at each, which
 * merge into one span.
 */
class TriangleSpansTest {

    /** A closed octahedron with outward (counter-clockwise) winding. */
    private static final double[] OCTA = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    private static final int[] OCTA_TRI = {
        0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
        2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5,
    };

    /** The octahedron's triangles as a set a structure can visit; only the visit is used here. */
    private static final PrimitiveSet TRIANGLES = new PrimitiveSet() {
        @Override public int size() { return 8; }
        @Override public void bounds(int i, double[] out) { throw new UnsupportedOperationException(); }
        @Override public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx) { throw new UnsupportedOperationException(); }
    };

    @Test
    void aLineThroughSharedVerticesCrossesEachTriangleThereAtTheSameT() {
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray().set(-5, 0, 0, 1, 0, 0, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
        for (int i = 0; i < 8; i++) TriangleSpans.addCrossing(OCTA_TRI, OCTA, i, ray, ctx);
        assertEquals(8, ctx.crossingCount, "four triangles meet at each of the two vertices");
        int entering = 0;
        for (int k = 0; k < 8; k++) {
            double t = ctx.crossings[4 * k];
            boolean in = ctx.crossings[4 * k + 1] >= 0;
            assertEquals(in ? 4.0 : 6.0, t, "crossing " + k);
            if (in) entering++;
        }
        assertEquals(4, entering);
    }

    @Test
    void theDuplicatesMergeIntoOneSpanClippedToNothingButTheInterval() {
        TraceContext ctx = new TraceContext();
        SpanBuffer out = new SpanBuffer();
        Ray ray = new Ray().set(-5, 0, 0, 1, 0, 0, 4.5, 5.5);
        TriangleSpans.spans(new BruteForce(TRIANGLES), (i, r, s) -> TriangleSpans.addCrossing(OCTA_TRI, OCTA, i, r, (TraceContext) s),
                null, ray, out, ctx);
        assertEquals(1, out.size());
        assertEquals(4.0, out.entry(0), "the true entry, outside the ray's interval");
        assertEquals(6.0, out.exit(0));
        assertEquals(4.5, ray.tMin, "the interval is given back");
        assertEquals(5.5, ray.tMax);
        Hit h = new Hit();
        out.toHit(0, h);
        assertTrue(h.prim >= 0 && h.prim < 8 && (OCTA_TRI[3 * h.prim] == 1 || OCTA_TRI[3 * h.prim + 1] == 1 || OCTA_TRI[3 * h.prim + 2] == 1),
                "the entry is on a triangle at vertex -x, found " + h.prim);
    }

    @Test
    void aLineGrazingAVertexFromOutsideHasNoSpan() {
        TraceContext ctx = new TraceContext();
        SpanBuffer out = new SpanBuffer();
        // Through vertex +z only, in the plane z = 1 along x: touches the solid at one point.
        Ray ray = new Ray().set(-5, 0, 1, 1, 0, 0, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
        TriangleSpans.spans(new BruteForce(TRIANGLES), (i, r, s) -> TriangleSpans.addCrossing(OCTA_TRI, OCTA, i, r, (TraceContext) s),
                null, ray, out, ctx);
        assertEquals(0, out.size());
    }
}
