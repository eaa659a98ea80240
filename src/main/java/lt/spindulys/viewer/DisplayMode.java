package lt.spindulys.viewer;

/** How the viewer shows a surface, Workframe's three ways. */
public enum DisplayMode {
    /** The faces of the surface at its level, flat shaded (at level 0, the control mesh). */
    POLYHEDRON("Polyhedron"),
    /** The control cage's edges only. */
    LATTICE("Lattice"),
    /** The surface refined to its level, smooth shaded with the limit normals. */
    SMOOTHED("Smoothed");

    private final String label;

    DisplayMode(String label) { this.label = label; }

    /** {@return the name shown in menus} */
    public String label() { return label; }
}
