package lt.spindulys.subdiv;

/** Uniform Catmull-Clark refinement with OpenSubdiv's rules. Stateless. */
public final class CatmullClark {
    private CatmullClark() {}

    /**
     * The mesh refined {@code level} times (0 gives the control mesh itself as a RefinedMesh).
     * {@link Subdivision#refine} does the same for a mesh of any scheme.
     *
     * @param mesh the control mesh, with the Catmull-Clark scheme
     * @param level refinements, at least 0
     * @return the refined mesh
     * @throws IllegalArgumentException if the mesh has another scheme
     */
    public static RefinedMesh refine(ControlMesh mesh, int level) {
        if (mesh.options().scheme() != SubdivOptions.Scheme.CATMARK) {
            throw new IllegalArgumentException("the mesh has the " + mesh.options().scheme().keyword() + " scheme, not Catmull-Clark");
        }
        return Subdivision.refine(mesh, level);
    }
}
