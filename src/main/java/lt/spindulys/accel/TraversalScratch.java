package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/**
 * Per-thread scratch of the acceleration structures' traversals: the per-direction constants of
 * the box and triangle tests and the traversal stack, so traversal allocates nothing. The scene's
 * per-thread context extends it with its own scratch. Never shared between threads.
 */
public class TraversalScratch {
    /** Scratch record for any-hit tests of a primitive set that has no test of its own. */
    public final PrimitiveHit anyHit = new PrimitiveHit();

    /**
     * Entries of {@link #stack(int)} below this index belong to traversals further up the call
     * chain (a scene BVH whose primitive is a mesh with its own BVH): a traversal uses the entries
     * from here on and raises it while it calls its primitives.
     */
    public int stackTop;

    /**
     * Per-direction constants, valid while the ray direction equals (dirX, dirY, dirZ) (see
     * {@link #direction(Ray)}): the inverse direction of the box tests, and the axis permutation
     * and shear of the watertight triangle test. A scene structure and the meshes it holds see
     * the same direction (unless an object is transformed), so they are computed once per ray.
     */
    public double dirX = Double.NaN, dirY = Double.NaN, dirZ = Double.NaN;
    public double invX, invY, invZ;
    public double shearSx, shearSy, shearSz;
    public int shearKx, shearKy, shearKz;

    /** Per-lane scratch of the wide BVH's vector box test, and its per-ray constants. */
    public final float[] lanes = new float[8], wideRay = new float[9];

    /** Per-ray constants of the float triangle test of a wide tree's leaves ({@link TriangleBlocks#prepare}). */
    final float[] blockRay = new float[6];

    /**
     * The triangle whose any-hit test ({@link WatertightTriangles#test} without a hit record) last
     * returned true on this thread, for the scene's occluder cache; not reset by other queries.
     */
    public int blockingPrimitive = -1;

    /**
     * Whether the traversal counters are on: {@code -Dspindulys.counters=true} on the JVM's
     * command line. Read once into a constant, so that with it off the JIT drops every counting
     * statement ({@code if (COUNTING) ...}) and traversal costs what it did without them.
     */
    public static final boolean COUNTING = Boolean.getBoolean("spindulys.counters");

    /** Ray kinds of the counters ({@link #rayKind}): camera rays, shadow rays, reflected and refracted rays. */
    public static final int CAMERA = 0, SHADOW = 1, SECONDARY = 2, KINDS = 3;

    /** The kind of the ray being traced, which the counters are charged to; set by the integrator when {@link #COUNTING}. */
    public int rayKind;

    /**
     * Traversal counts of this thread by {@link #rayKind}, only while {@link #COUNTING}: inner
     * nodes visited (one node = the box tests of its children, whether two or eight), leaves
     * entered (their primitives tested), and ray/triangle tests (each triangle a leaf or a tiny
     * mesh tests, including those a shadow ray's occluder cache tries first).
     */
    public final long[] nodesVisited = new long[KINDS], leavesEntered = new long[KINDS], triangleTests = new long[KINDS];

    private int[] stack = new int[64];

    /** Makes the per-direction constants those of {@code ray}'s direction. */
    public void direction(Ray ray) {
        double dx = ray.dx, dy = ray.dy, dz = ray.dz;
        if (dx == dirX && dy == dirY && dz == dirZ) return;
        invX = 1 / dx; invY = 1 / dy; invZ = 1 / dz;
        // kz is the dominant axis; kx, ky are swapped when the ray runs along -kz so that the
        // winding (and with it the sign of the edge functions) is preserved.
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        double dkz = kz == 0 ? dx : kz == 1 ? dy : dz;
        if (dkz < 0) { int t = kx; kx = ky; ky = t; }
        double dkx = kx == 0 ? dx : kx == 1 ? dy : dz;
        double dky = ky == 0 ? dx : ky == 1 ? dy : dz;
        shearKx = kx; shearKy = ky; shearKz = kz;
        shearSx = dkx / dkz;
        shearSy = dky / dkz;
        shearSz = 1 / dkz;
        dirX = dx; dirY = dy; dirZ = dz;
    }

    /** A traversal stack of at least {@code size} entries (grown once, then reused). */
    public int[] stack(int size) {
        if (stack.length < size) stack = new int[Math.max(size, stack.length * 2)];
        return stack;
    }
}
