package lt.spindulys.texture;

import lt.spindulys.math.Vec3;

/**
 * Cylindrical mapping about an axis through a centre: with d = p - c split into a = d . r,
 * b = d . (n x r), h = d . n, u = (atan2(b, a) / 2 pi mod 1) / su (around the axis, 0 along r)
 * and v = h / sv (along the axis, 0 at the centre). On the axis itself u is 0.
 */
public final class Cylindrical implements Mapping {
    private final MappingFrame f;

    /**
     * @param centre    a point on the axis, where v = 0
     * @param axis      the cylinder's axis, direction of +v
     * @param reference the direction of u = 0 (the seam), made perpendicular to the axis
     * @param su        turns per repeat along u
     * @param sv        object-space height of one repeat along v
     */
    public Cylindrical(Vec3 centre, Vec3 axis, Vec3 reference, double su, double sv) {
        f = new MappingFrame(centre, axis, reference, su, sv);
    }

    @Override
    public void map(double u, double v, double[] dpdu, double[] dpdv, double[] p, TexturePoint out) {
        double dx = p[0] - f.cx, dy = p[1] - f.cy, dz = p[2] - f.cz;
        double a = dx * f.rx + dy * f.ry + dz * f.rz;
        double b = dx * f.bx + dy * f.by + dz * f.bz;
        double h = dx * f.nx + dy * f.ny + dz * f.nz;
        double rho = Math.sqrt(a * a + b * b);
        out.u = MappingFrame.turn(a, b) / f.su;
        out.v = h / f.sv;
        MappingFrame.solid(p, out);
        double w = out.footprint;
        out.footprint = Mapping.combine(w, w / (2 * Math.PI * rho * f.su), w / f.sv);
    }
}
