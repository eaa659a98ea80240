package lt.spindulys.texture;

import lt.spindulys.math.Vec3;

/**
 * Planar projection along the axis n: with d = p - c, u = (d . r) / su and v = (d . (n x r)) / sv,
 * so one repeat of the texture covers su by sv object-space units. Points along n share (u, v).
 * Seen from the side n points to, with n x r up, r points right: the image is not mirrored.
 */
public final class Planar implements Mapping {
    private final MappingFrame f;

    /**
     * @param centre    the point mapped to (0, 0)
     * @param axis      the projection direction (normal of the texture's plane)
     * @param reference the direction of +u (made perpendicular to the axis)
     * @param su        object-space width of one repeat along u
     * @param sv        object-space width of one repeat along v
     */
    public Planar(Vec3 centre, Vec3 axis, Vec3 reference, double su, double sv) {
        f = new MappingFrame(centre, axis, reference, su, sv);
    }

    @Override
    public void map(double u, double v, double[] dpdu, double[] dpdv, double[] p, TexturePoint out) {
        double dx = p[0] - f.cx, dy = p[1] - f.cy, dz = p[2] - f.cz;
        out.u = (dx * f.rx + dy * f.ry + dz * f.rz) / f.su;
        out.v = (dx * f.bx + dy * f.by + dz * f.bz) / f.sv;
        MappingFrame.solid(p, out);
        double w = out.footprint;
        out.footprint = Mapping.combine(w, w / f.su, w / f.sv);
    }
}
