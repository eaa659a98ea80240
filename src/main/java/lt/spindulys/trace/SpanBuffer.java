package lt.spindulys.trace;

import lt.spindulys.material.Material;

/**
 * The intervals along a ray that lie inside a closed solid: sorted, disjoint [entry, exit] pairs,
 * each endpoint with the surface that bounds it (object, primitive, parameters), so CSG can pick
 * a span boundary and shade it like an ordinary hit. Endpoints may be infinite (a half-space).
 * Grows on demand; reused from per-thread scratch, so no allocation in steady state.
 */
public final class SpanBuffer {
    private int count;
    private double[] t = new double[8];
    private TracedObject[] object = new TracedObject[8];
    private int[] prim = new int[8], sub = new int[8];
    private double[] u = new double[8], v = new double[8];
    private boolean[] flip = new boolean[8];
    private Material[] material = new Material[8];
    /** The CSG node whose material overrides the endpoint's, else null (see {@link Hit#materialSpace}). */
    private TracedObject[] space = new TracedObject[8];

    public void clear() { count = 0; }

    /** Number of spans (half the number of endpoints). */
    public int size() { return count; }

    /** Appends a span; spans must be appended in increasing, non-overlapping order. */
    public void add(double tIn, TracedObject oIn, int pIn, double uIn, double vIn,
                    double tOut, TracedObject oOut, int pOut, double uOut, double vOut) {
        add(tIn, oIn, pIn, 0, uIn, vIn, tOut, oOut, pOut, 0, uOut, vOut);
    }

    /** {@link #add}, with the primitives' parts (see {@link lt.spindulys.accel.PrimitiveHit#sub}). */
    public void add(double tIn, TracedObject oIn, int pIn, int sIn, double uIn, double vIn,
                    double tOut, TracedObject oOut, int pOut, int sOut, double uOut, double vOut) {
        int i = 2 * count;
        ensure(i + 2);
        setEndpoint(i, tIn, oIn, pIn, sIn, uIn, vIn, false, oIn == null ? null : oIn.material(pIn, sIn), null);
        setEndpoint(i + 1, tOut, oOut, pOut, sOut, uOut, vOut, false, oOut == null ? null : oOut.material(pOut, sOut), null);
        count++;
    }

    /** Appends one endpoint copied from another buffer; pairs of calls make a span. */
    public void addEndpoint(SpanBuffer from, int endpoint, boolean flipNormal) {
        int i = 2 * count + pending;
        ensure(i + 1);
        setEndpoint(i, from.t[endpoint], from.object[endpoint], from.prim[endpoint], from.sub[endpoint], from.u[endpoint], from.v[endpoint],
                from.flip[endpoint] ^ flipNormal, from.material[endpoint], from.space[endpoint]);
        if (++pending == 2) { pending = 0; count++; }
    }

    private int pending;

    private void setEndpoint(int i, double tt, TracedObject o, int p, int ps, double uu, double vv, boolean f, Material m, TracedObject s) {
        t[i] = tt; object[i] = o; prim[i] = p; sub[i] = ps; u[i] = uu; v[i] = vv; flip[i] = f; material[i] = m; space[i] = s;
    }

    /**
     * Makes {@code o} the surface (and its material for the endpoint's primitive) of every endpoint of the
     * spans from {@code fromSpan} on: for an object that reports the spans of an inner object it
     * owns, so that they are shaded through the outer one.
     */
    public void relabel(int fromSpan, TracedObject o) {
        for (int i = 2 * fromSpan; i < 2 * count; i++) {
            object[i] = o;
            material[i] = o.material(prim[i], sub[i]);
            space[i] = null;
        }
    }

    /**
     * Overrides the material of every endpoint: {@code owner}, an enclosing CSG node, has its own
     * material {@code m}, which maps textures in the owner's space.
     */
    public void overrideMaterial(Material m, TracedObject owner) {
        for (int i = 0; i < 2 * count; i++) {
            material[i] = m;
            space[i] = owner;
        }
    }

    public double entry(int span) { return t[2 * span]; }
    public double exit(int span) { return t[2 * span + 1]; }
    public double t(int endpoint) { return t[endpoint]; }

    /** Copies endpoint {@code endpoint} (2*span for the entry, 2*span+1 for the exit) into a hit. */
    public void toHit(int endpoint, Hit hit) {
        hit.t = t[endpoint];
        hit.object = object[endpoint];
        hit.prim = prim[endpoint];
        hit.sub = sub[endpoint];
        hit.u = u[endpoint];
        hit.v = v[endpoint];
        hit.flipNormal = flip[endpoint];
        hit.material = material[endpoint];
        hit.materialSpace = space[endpoint];
    }

    private void ensure(int endpoints) {
        if (endpoints <= t.length) return;
        int n = Math.max(endpoints, t.length * 2);
        t = java.util.Arrays.copyOf(t, n);
        object = java.util.Arrays.copyOf(object, n);
        prim = java.util.Arrays.copyOf(prim, n);
        sub = java.util.Arrays.copyOf(sub, n);
        u = java.util.Arrays.copyOf(u, n);
        v = java.util.Arrays.copyOf(v, n);
        flip = java.util.Arrays.copyOf(flip, n);
        material = java.util.Arrays.copyOf(material, n);
        space = java.util.Arrays.copyOf(space, n);
    }
}
