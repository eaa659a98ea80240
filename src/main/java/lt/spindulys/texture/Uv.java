package lt.spindulys.texture;

/**
 * The surface's own coordinates, divided by the scales and moved by the offsets:
 * (u / su + ou, v / sv + ov); the scene language's uv mapping has no offset (0), a .mtl file's
 * texture options {@code -s} and {@code -o} give both. These are the OBJ {@code vt}
 * coordinates on meshes, the face-varying UVs refined with a subdivision surface (a .tex unwrap
 * included), and each primitive's parametrisation otherwise (a sphere's longitude/colatitude, a
 * plane's tangent coordinates). The footprint is converted with the object-space lengths of
 * dp/du and dp/dv.
 */
public final class Uv implements Mapping {
    private final double su, sv, ou, ov;

    /**
     * A mapping that scales the surface's own coordinates.
     *
     * @param su surface units per repeat along u (1: the coordinates as they are)
     * @param sv surface units per repeat along v
     */
    public Uv(double su, double sv) {
        this(su, sv, 0, 0);
    }

    /**
     * A mapping that scales the surface's own coordinates, then moves them.
     *
     * @param su surface units per repeat along u (1: the coordinates as they are)
     * @param sv surface units per repeat along v
     * @param ou added to u after scaling
     * @param ov added to v after scaling
     */
    public Uv(double su, double sv, double ou, double ov) {
        if (!Double.isFinite(ou) || !Double.isFinite(ov)) throw new IllegalArgumentException("offset must be finite, found " + ou + " " + ov);
        this.ou = ou;
        this.ov = ov;
        if (!(su > 0) || !(sv > 0) || !Double.isFinite(su) || !Double.isFinite(sv)) {
            throw new IllegalArgumentException("scale must be positive, found " + su + " " + sv);
        }
        this.su = su;
        this.sv = sv;
    }

    @Override
    public void map(double u, double v, double[] du, double[] dv, double[] p, TexturePoint out) {
        out.u = u / su + ou;
        out.v = v / sv + ov;
        MappingFrame.solid(p, out);
        double w = out.footprint;
        double lu = Math.sqrt(du[0] * du[0] + du[1] * du[1] + du[2] * du[2]);
        double lv = Math.sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]);
        out.footprint = Mapping.combine(w, w / (lu * su), w / (lv * sv));
    }
}
