package lt.spindulys.texture;

import lt.spindulys.math.Vec3;

/**
 * Polar (latitude-longitude) mapping about a centre: with d = p - c split into a = d . r,
 * b = d . (n x r), h = d . n, u = (atan2(b, a) / 2 pi mod 1) / su (longitude, 0 along r) and
 * v = (1/2 + atan2(h, sqrt(a^2 + b^2)) / pi) / sv (latitude, 0 at the south pole -n, 1 at the
 * north pole +n); u grows counter-clockwise seen from the north pole, so that an image seen
 * from outside is not mirrored. The seam u = 0/1 lies along r; at the poles and the centre, where longitude is
 * undefined, u is 0. Footprints come from the analytic derivatives (see {@link Mapping}).
 */
public final class Spherical implements Mapping {
    private final MappingFrame f;

    /**
     * @param centre    the centre of the sphere of directions
     * @param axis      towards the north pole (v = 1)
     * @param reference the direction of longitude 0 (the seam), made perpendicular to the axis
     * @param su        turns per repeat along u (1: the texture wraps once around)
     * @param sv        pole-to-pole spans per repeat along v (1: once from pole to pole)
     */
    public Spherical(Vec3 centre, Vec3 axis, Vec3 reference, double su, double sv) {
        f = new MappingFrame(centre, axis, reference, su, sv);
    }

    @Override
    public void map(double u, double v, double[] dpdu, double[] dpdv, double[] p, TexturePoint out) {
        double dx = p[0] - f.cx, dy = p[1] - f.cy, dz = p[2] - f.cz;
        double a = dx * f.rx + dy * f.ry + dz * f.rz;
        double b = dx * f.bx + dy * f.by + dz * f.bz;
        double h = dx * f.nx + dy * f.ny + dz * f.nz;
        double rho = Math.sqrt(a * a + b * b);
        double len = Math.sqrt(rho * rho + h * h);
        out.u = MappingFrame.turn(a, b) / f.su;
        out.v = (0.5 + Math.atan2(h, rho) / Math.PI) / f.sv;
        MappingFrame.solid(p, out);
        // A step w along the surface moves longitude by w / (2 pi rho) turns, latitude by w / (pi len).
        double w = out.footprint;
        out.footprint = Mapping.combine(w, w / (2 * Math.PI * rho * f.su), w / (Math.PI * len * f.sv));
    }
}
