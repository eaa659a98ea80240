package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Vec3;

/** Known points map to known (u, v), including seams and poles, and footprints stay bounded there. */
class MappingTest {
    private static final double EPS = 1e-12;
    /** The surface parameters handed to the mapping. */
    private double u, v;
    private final double[] dpdu = new double[3], dpdv = new double[3];
    private final TexturePoint tp = new TexturePoint();

    private TexturePoint map(Mapping m, double x, double y, double z, double footprint) {
        tp.footprint = footprint;
        m.map(u, v, dpdu, dpdv, new double[] {x, y, z}, tp);
        return tp;
    }

    private static Spherical sphere() { return new Spherical(Vec3.ZERO, Vec3.Y, Vec3.X, 1, 1); }

    @Test
    void planarProjectsAlongTheAxis() {
        Planar p = new Planar(new Vec3(1, 0, 0), Vec3.Z, Vec3.X, 2, 4);
        map(p, 3, 2, 7, 0); // d = (2, 2, 7): u = d.x / 2, v = d.(z x x = y) / 4
        assertEquals(1.0, tp.u, EPS);
        assertEquals(0.5, tp.v, EPS);
        assertEquals(7.0, tp.z, EPS);
        map(p, 3, 2, -100, 0.4); // the depth along the axis does not matter
        assertEquals(1.0, tp.u, EPS);
        assertEquals(0.2, tp.footprint, EPS); // the larger of 0.4/2 and 0.4/4, within the anisotropy cap
    }

    @Test
    void sphericalLongitudeAndLatitude() {
        Spherical s = sphere();
        map(s, 1, 0, 0, 0);
        assertEquals(0.0, tp.u, EPS);
        assertEquals(0.5, tp.v, EPS);
        // u grows from +x towards n x r = y x x = -z: counter-clockwise seen from the north pole
        map(s, 0, 0, -1, 0);
        assertEquals(0.25, tp.u, EPS);
        map(s, -1, 0, 0, 0);
        assertEquals(0.5, tp.u, EPS);
        map(s, 0, 0, 1, 0);
        assertEquals(0.75, tp.u, EPS);
        map(s, Math.sqrt(0.5), Math.sqrt(0.5), 0, 0); // 45 degrees north
        assertEquals(0.75, tp.v, EPS);
        map(s, 0, 0, 2, 0); // only the direction from the centre matters
        assertEquals(0.75, tp.u, EPS);
        assertEquals(0.5, tp.v, EPS);
    }

    @Test
    void sphericalSeamIsContinuousAndInRange() {
        Spherical s = sphere();
        map(s, 1, 0, 1e-9, 0); // b = -z: positive z is just before the seam
        double justBefore = tp.u;
        map(s, 1, 0, -1e-9, 0);
        double justAfter = tp.u;
        assertTrue(justBefore < 1 && justBefore > 1 - 1e-8, "before the seam " + justBefore);
        assertTrue(justAfter >= 0 && justAfter < 1e-8, "after the seam " + justAfter);
        map(s, 1, 0, 0.0, 0);
        assertEquals(0.0, tp.u); // never 1, never -0
        // The footprint on both sides of the seam is the same (analytic, not differenced)
        map(s, 1, 0, -1e-9, 0.01);
        double f1 = tp.footprint;
        map(s, 1, 0, 1e-9, 0.01);
        assertEquals(f1, tp.footprint, 1e-12);
        assertEquals(0.01 / Math.PI, f1, 1e-9); // latitude rate 1/(pi r) is the larger near the equator
    }

    @Test
    void sphericalPolesAreWellDefined() {
        Spherical s = sphere();
        map(s, 0, 1, 0, 0.01);
        assertEquals(0.0, tp.u);
        assertEquals(1.0, tp.v, EPS);
        // At the pole longitude changes infinitely fast: the footprint is capped at 4x latitude's
        assertEquals(4 * 0.01 / Math.PI, tp.footprint, 1e-12);
        map(s, 0, -3, 0, 0);
        assertEquals(0.0, tp.u);
        assertEquals(0.0, tp.v, EPS);
        map(s, 0, 0, 0, 0.01); // the centre itself
        assertEquals(0.0, tp.u);
        assertEquals(0.5, tp.v, EPS);
        assertTrue(Double.isFinite(tp.footprint));
    }

    @Test
    void sphericalFrameAndScale() {
        // Pole along +z, seam along +y, texture repeated twice around and once pole to pole.
        Spherical s = new Spherical(new Vec3(0, 0, 5), Vec3.Z, new Vec3(0, 1, 3), 0.5, 1);
        map(s, 0, 1, 5, 0);
        assertEquals(0.0, tp.u, EPS);
        assertEquals(0.5, tp.v, EPS);
        // b = n x r = z x y = -x; u grows towards b: a quarter turn, doubled by su = 0.5
        map(s, -1, 0, 5, 0);
        assertEquals(0.5, tp.u, EPS);
        map(s, 0, 0, 9, 0);
        assertEquals(1.0, tp.v, EPS);
    }

    @Test
    void cylindricalAroundAndAlong() {
        Cylindrical c = new Cylindrical(new Vec3(0, 1, 0), Vec3.Y, Vec3.X, 1, 2);
        map(c, 1, 1, 0, 0);
        assertEquals(0.0, tp.u, EPS);
        assertEquals(0.0, tp.v, EPS);
        map(c, 0, 5, -2, 0);
        assertEquals(0.25, tp.u, EPS);
        assertEquals(2.0, tp.v, EPS);
        map(c, -1, -1, 0, 0);
        assertEquals(0.5, tp.u, EPS);
        assertEquals(-1.0, tp.v, EPS);
        map(c, 0, 3, 0, 0.2); // on the axis: u defined, footprint capped
        assertEquals(0.0, tp.u);
        assertEquals(4 * 0.1, tp.footprint, 1e-12);
        map(c, 1, 0, 0, 0.2); // radius 1: around 0.2/(2 pi), along 0.2/2, the larger
        assertEquals(0.1, tp.footprint, 1e-12);
        map(c, 2, 0, 0, 0.2); // radius 2: around 0.2/(4 pi) is less than a quarter of along: capped
        assertEquals(4 * 0.2 / (4 * Math.PI), tp.footprint, 1e-12);
    }

    @Test
    void uvUsesTheSurfaceCoordinates() {
        Uv m = new Uv(0.5, 2);
        u = 0.3;
        v = 0.8;
        dpdu[0] = 2; dpdu[1] = dpdu[2] = 0;
        dpdv[1] = 4; dpdv[0] = dpdv[2] = 0;
        map(m, 7, 8, 9, 0.4);
        assertEquals(0.6, tp.u, EPS);
        assertEquals(0.4, tp.v, EPS);
        assertEquals(9.0, tp.z);
        // along u: 0.4 / (2 * 0.5) = 0.4; along v: 0.4 / (4 * 2) = 0.05; capped at 4x the smaller
        assertEquals(0.2, tp.footprint, 1e-12);
        dpdu[0] = 0; // a degenerate direction (a sphere's pole) does not blow up
        map(m, 0, 0, 0, 0.4);
        assertEquals(0.2, tp.footprint, 1e-12);
    }

    @Test
    void invalidFramesAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new Spherical(Vec3.ZERO, Vec3.Y, new Vec3(0, 2, 0), 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new Planar(Vec3.ZERO, Vec3.ZERO, Vec3.X, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new Cylindrical(Vec3.ZERO, Vec3.Y, Vec3.X, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new Uv(1, -1));
    }
}
