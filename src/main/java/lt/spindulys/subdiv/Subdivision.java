package lt.spindulys.subdiv;

/**
 * Uniform refinement of a control mesh with its own scheme ({@link SubdivOptions#scheme()}):
 * Catmull-Clark, Loop or bilinear, each with OpenSubdiv's rules. Stateless.
 */
public final class Subdivision {
    private Subdivision() {}

    /**
     * The mesh refined {@code level} times with its scheme (0 gives the control mesh itself as a
     * RefinedMesh).
     *
     * @param mesh the control mesh
     * @param level refinements, at least 0
     * @return the refined mesh
     */
    public static RefinedMesh refine(ControlMesh mesh, int level) {
        if (level < 0) throw new IllegalArgumentException("refinement level " + level + " is negative");
        RefinedMesh r = RefinedMesh.base(mesh);
        for (int i = 0; i < level; i++) {
            RefinedMesh next = r.refine();
            if (i == level - 1) next.compactAfter(r);
            r = next;
        }
        return r;
    }
}
