package lt.spindulys.scene;

import java.util.ArrayList;
import java.util.List;

import lt.spindulys.accel.Accelerator;
import lt.spindulys.accel.BruteForce;
import lt.spindulys.accel.Bvh;
import lt.spindulys.accel.Octree;
import lt.spindulys.accel.PrimitiveSet;
import lt.spindulys.accel.WideBvh;

/**
 * The acceleration structures to choose from, by name: one switch for both levels, the scene's
 * structure over its objects and each mesh's over its triangles. A user setting
 * (in {@link RenderSettings}), so it lives beside the settings; the structures
 * themselves are internal.
 */
public enum AcceleratorKind {
    /**
     * The default, the fastest in our measurements: a {@link Bvh} collapsed to a {@link WideBvh}
     * whose eight boxes per node are tested with one vector pass when the JVM has the
     * {@code jdk.incubator.vector} module, a mesh's leaves holding up to eight triangles whose
     * corners are copied into them in float and tested together (when the heap has room for the
     * copies; otherwise as {@link #BVH_COMPACT}); without the module the binary {@link Bvh}.
     */
    BVH("bvh") {
        @Override Accelerator build(PrimitiveSet set) { return WideBvh.build(set, true); }
    },
    /**
     * {@link #BVH} without the copies: leaves of up to four triangles that name them, about 36
     * bytes a triangle less, for meshes that would not fit the heap otherwise.
     */
    BVH_COMPACT("bvh-compact") {
        @Override Accelerator build(PrimitiveSet set) { return WideBvh.widen(new Bvh(set)); }
    },
    /** {@link Bvh}: the binary binned-SAH hierarchy with scalar box tests, whatever the JVM. */
    BVH2("bvh2") {
        @Override Accelerator build(PrimitiveSet set) { return new Bvh(set); }
    },
    /** {@link Octree}: the thesis's octree, front-to-back traversal. */
    OCTREE("octree") {
        @Override Accelerator build(PrimitiveSet set) { return new Octree(set); }
    },
    /** {@link BruteForce}: tests every primitive; for testing and debugging. */
    BRUTE_FORCE("bruteforce") {
        @Override Accelerator build(PrimitiveSet set) { return new BruteForce(set); }
    };

    /** The structure used when none is chosen. */
    public static final AcceleratorKind DEFAULT = BVH;

    private final String keyword;

    AcceleratorKind(String keyword) { this.keyword = keyword; }

    /** Builds this kind of structure over {@code set}; the scene's own business, hence not public. */
    abstract Accelerator build(PrimitiveSet set);

    /** {@link #build}, on the calling thread alone (a render thread refining a lazy patch). */
    Accelerator buildOnThisThread(PrimitiveSet set) {
        return switch (this) {
            case BVH -> WideBvh.build(set, false);
            case BVH_COMPACT -> WideBvh.widen(new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, false));
            case BVH2 -> new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, false);
            default -> build(set);
        };
    }

    /**
     * What this kind builds in this JVM, for statistics: for {@link #BVH}, whether the wide vector
     * form or the binary fallback (the module missing, or vectors under 256 bits).
     *
     * @return one line for the statistics
     */
    public String description() {
        return switch (this) {
            case BVH -> WideBvh.AVAILABLE ? "bvh: 8 children per node, vector box tests, triangles in the leaves"
                    : "bvh: binary, scalar box tests (the JVM has no jdk.incubator.vector module or no 256-bit vectors)";
            case BVH_COMPACT -> WideBvh.AVAILABLE ? "bvh-compact: 8 children per node, vector box tests, leaves naming their triangles"
                    : "bvh-compact: binary, scalar box tests (the JVM has no jdk.incubator.vector module or no 256-bit vectors)";
            case BVH2 -> "bvh2: binary, scalar box tests";
            case OCTREE -> "octree";
            case BRUTE_FORCE -> "bruteforce: every primitive tested";
        };
    }

    /**
     * The name used in scene files and on the command line, for example "bruteforce".
     *
     * @return the keyword
     */
    public String keyword() { return keyword; }

    /**
     * The keywords of all kinds, in declaration order.
     *
     * @return the keywords
     */
    public static List<String> keywords() {
        List<String> k = new ArrayList<>();
        for (AcceleratorKind a : values()) k.add(a.keyword);
        return k;
    }

    /**
     * The kind named {@code keyword}.
     *
     * @param keyword the keyword
     * @return the kind
     * @throws IllegalArgumentException "unknown accelerator 'kd' (expected one of bvh, bvh-compact, bvh2, octree, bruteforce)"
     */
    public static AcceleratorKind fromKeyword(String keyword) {
        for (AcceleratorKind a : values()) if (a.keyword.equals(keyword)) return a;
        throw new IllegalArgumentException("unknown accelerator '" + keyword + "' (expected one of " + String.join(", ", keywords()) + ")");
    }
}
