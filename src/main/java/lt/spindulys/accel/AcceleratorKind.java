package lt.spindulys.accel;

import java.util.ArrayList;
import java.util.List;

/**
 * The acceleration structures to choose from, by name: one switch for both levels, the scene's
 * structure over its objects and each mesh's over its triangles.
 */
public enum AcceleratorKind {
    /** {@link Bvh}: binned-SAH bounding volume hierarchy, the default (faster in our measurements). */
    BVH("bvh") {
        @Override public Accelerator build(PrimitiveSet set) { return new Bvh(set); }
    },
    /** {@link Octree}: the thesis's octree, front-to-back traversal. */
    OCTREE("octree") {
        @Override public Accelerator build(PrimitiveSet set) { return new Octree(set); }
    },
    /** {@link BruteForce}: tests every primitive; for testing and debugging. */
    BRUTE_FORCE("bruteforce") {
        @Override public Accelerator build(PrimitiveSet set) { return new BruteForce(set); }
    };

    /** The structure used when none is chosen. */
    public static final AcceleratorKind DEFAULT = BVH;

    private final String keyword;

    AcceleratorKind(String keyword) { this.keyword = keyword; }

    /** Builds this kind of structure over {@code set}. */
    public abstract Accelerator build(PrimitiveSet set);

    /** The name used in scene files and on the command line, for example "bruteforce". */
    public String keyword() { return keyword; }

    /** The keywords of all kinds, in declaration order. */
    public static List<String> keywords() {
        List<String> k = new ArrayList<>();
        for (AcceleratorKind a : values()) k.add(a.keyword);
        return k;
    }

    /**
     * The kind named {@code keyword}.
     *
     * @throws IllegalArgumentException "unknown accelerator 'kd' (expected one of bvh, octree, bruteforce)"
     */
    public static AcceleratorKind fromKeyword(String keyword) {
        for (AcceleratorKind a : values()) if (a.keyword.equals(keyword)) return a;
        throw new IllegalArgumentException("unknown accelerator '" + keyword + "' (expected one of " + String.join(", ", keywords()) + ")");
    }
}
