package lt.spindulys.texture;

import lt.spindulys.math.Vec3;

/**
 * The placement shared by the projection mappings: a centre c, a unit axis n, a unit reference
 * direction r (the given one made perpendicular to n), b = n x r completing a right-handed frame,
 * and the scales (su, sv) that divide the natural coordinates. Immutable.
 */
final class MappingFrame {
    final double cx, cy, cz, nx, ny, nz, rx, ry, rz, bx, by, bz, su, sv;

    MappingFrame(Vec3 centre, Vec3 axis, Vec3 reference, double su, double sv) {
        if (!centre.isFinite() || !axis.isFinite() || !reference.isFinite()) throw new IllegalArgumentException("center, axis and reference must be finite");
        if (!(axis.length() > 0)) throw new IllegalArgumentException("axis has zero length");
        if (!(su > 0) || !(sv > 0) || !Double.isFinite(su) || !Double.isFinite(sv)) {
            throw new IllegalArgumentException("scale must be positive, found " + su + " " + sv);
        }
        Vec3 n = axis.normalized();
        Vec3 r = reference.minus(n.times(reference.dot(n)));
        if (!(r.length() > 1e-9 * Math.max(1, reference.length()))) {
            throw new IllegalArgumentException("reference direction " + reference + " is parallel to the axis " + axis);
        }
        r = r.normalized();
        Vec3 b = n.cross(r);
        cx = centre.x(); cy = centre.y(); cz = centre.z();
        nx = n.x(); ny = n.y(); nz = n.z();
        rx = r.x(); ry = r.y(); rz = r.z();
        bx = b.x(); by = b.y(); bz = b.z();
        this.su = su; this.sv = sv;
    }

    /** Copies the object point to the solid-texture coordinates. */
    static void solid(double[] p, TexturePoint out) {
        out.x = p[0]; out.y = p[1]; out.z = p[2];
    }

    /**
     * Longitude around the axis as a fraction of a turn in [0, 1): 0 along r, increasing from r
     * towards b = n x r (counter-clockwise seen from +n), so that seen from outside with n up, u
     * grows to the right (an image is not mirrored). At the axis itself (undefined longitude) it is 0.
     */
    static double turn(double a, double b) {
        double t = Math.atan2(b, a) / (2 * Math.PI) + 0.0; // + 0.0 turns -0.0 into 0.0
        if (t < 0) t += 1;
        return t >= 1 ? 0 : t; // -0.0 and tiny negatives round up to exactly 1
    }
}
