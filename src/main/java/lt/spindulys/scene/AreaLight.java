package lt.spindulys.scene;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Vec3;

/**
 * A light with an extent, casting soft shadows (distributed ray tracing, Cook et al. 1984): a
 * rectangle, a disc or a sphere that emits radiance color * intensity from every point of its
 * surface. Shading sends {@link #samples()} shadow rays to it per pixel sample, to points spread
 * over it in strata shared by the pixel's samples; the noise of a soft shadow's estimate falls as
 * 1/sqrt(samples per pixel * samples). Camera, reflected and refracted rays that reach it see its
 * radiance. It is not scene geometry: it casts no shadow, on itself or anything else.
 *
 * <p>A rectangle or disc emits from both faces, or with {@link #oneSided()} only towards its
 * normal (its back is then black); a sphere emits outwards. Its irradiance at a point is, in the
 * same units as a point light's intensity, the integral of radiance * cos over the solid angle it
 * fills: a disc of radius R seen on its axis from distance d gives intensity * pi R^2 / (d^2 + R^2).
 */
public final class AreaLight {
    /** The light's shape. */
    public enum Shape {
        /** A rectangle: centre, normal, a tangent along its width, width and height. */
        RECTANGLE,
        /** A disc: centre, normal and radius. */
        DISC,
        /** A sphere: centre and radius. */
        SPHERE
    }

    /** Largest number of shadow rays to one light per pixel sample. */
    public static final int MAX_SAMPLES = 1024;

    private final Shape shape;
    private final Vec3 center, normal, u, v;
    private final double radius, area;
    private final Color color;
    private final double intensity;
    private final boolean oneSided;
    private final int samples;

    private AreaLight(Shape shape, Vec3 center, Vec3 normal, Vec3 u, Vec3 v, double radius, double area,
                      Color color, double intensity, boolean oneSided, int samples) {
        Ranges.modest("area light center", center);
        Ranges.colour("area light color", color, Ranges.MAX_COLOUR);
        Ranges.inRange("area light intensity", intensity, Ranges.MAX_INTENSITY);
        if (samples < 1 || samples > MAX_SAMPLES) {
            throw new IllegalArgumentException("area light samples must be 1.." + MAX_SAMPLES + ", found " + samples);
        }
        this.shape = shape;
        this.center = center;
        this.normal = normal;
        this.u = u;
        this.v = v;
        this.radius = radius;
        this.area = area;
        this.color = color;
        this.intensity = intensity;
        this.oneSided = oneSided;
        this.samples = samples;
    }

    /** The unit normal of a rectangle or disc, checked non-zero. */
    private static Vec3 unitNormal(Vec3 n) {
        Ranges.modest("area light normal", n);
        double l = n.length();
        if (!(l > 0) || !Double.isFinite(l)) throw new IllegalArgumentException("area light normal must not be zero, found " + n);
        return n.times(1 / l);
    }

    private static double size(String what, double s) {
        if (!(s > 0) || !Ranges.isModest(s)) throw new IllegalArgumentException("area light " + what + " must be positive and at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + s);
        return s;
    }

    /**
     * A rectangle light.
     *
     * @param center    its centre
     * @param normal    its normal (the emitting side when one-sided), not zero
     * @param tangent   the direction of its width: projected into its plane; not parallel to the normal
     * @param width     its extent along the tangent, positive
     * @param height    its extent along normal x tangent, positive
     * @param color     its colour, components 0..100
     * @param intensity its radiance scale, 0..1e15
     * @param oneSided  whether it emits only towards its normal
     * @param samples   shadow rays per pixel sample, 1..{@link #MAX_SAMPLES}
     * @return the light
     * @throws IllegalArgumentException naming the value out of range
     */
    public static AreaLight rectangle(Vec3 center, Vec3 normal, Vec3 tangent, double width, double height,
                                      Color color, double intensity, boolean oneSided, int samples) {
        Vec3 n = unitNormal(normal);
        Ranges.modest("area light tangent", tangent);
        Vec3 t = tangent.minus(n.times(tangent.dot(n)));
        double tl = t.length();
        if (!(tl > 1e-9 * tangent.length())) throw new IllegalArgumentException("area light tangent must not be parallel to its normal, found " + tangent);
        t = t.times(1 / tl);
        Vec3 b = n.cross(t);
        size("width", width);
        size("height", height);
        return new AreaLight(Shape.RECTANGLE, center, n, t.times(width / 2), b.times(height / 2), 0, width * height,
                color, intensity, oneSided, samples);
    }

    /**
     * A disc light.
     *
     * @param center    its centre
     * @param normal    its normal (the emitting side when one-sided), not zero
     * @param radius    its radius, positive
     * @param color     its colour, components 0..100
     * @param intensity its radiance scale, 0..1e15
     * @param oneSided  whether it emits only towards its normal
     * @param samples   shadow rays per pixel sample, 1..{@link #MAX_SAMPLES}
     * @return the light
     * @throws IllegalArgumentException naming the value out of range
     */
    public static AreaLight disc(Vec3 center, Vec3 normal, double radius, Color color, double intensity, boolean oneSided, int samples) {
        Vec3 n = unitNormal(normal);
        size("radius", radius);
        // Any orthonormal pair in the plane: the disc is symmetric about its normal.
        Vec3 a = Math.abs(n.x()) < 0.9 ? Vec3.X : Vec3.Y;
        Vec3 t = a.minus(n.times(a.dot(n))).normalized();
        Vec3 b = n.cross(t);
        return new AreaLight(Shape.DISC, center, n, t.times(radius), b.times(radius), radius, Math.PI * radius * radius,
                color, intensity, oneSided, samples);
    }

    /**
     * A sphere light, emitting outwards.
     *
     * @param center    its centre
     * @param radius    its radius, positive
     * @param color     its colour, components 0..100
     * @param intensity its radiance scale, 0..1e15
     * @param samples   shadow rays per pixel sample, 1..{@link #MAX_SAMPLES}
     * @return the light
     * @throws IllegalArgumentException naming the value out of range
     */
    public static AreaLight sphere(Vec3 center, double radius, Color color, double intensity, int samples) {
        size("radius", radius);
        return new AreaLight(Shape.SPHERE, center, Vec3.Y, Vec3.X, Vec3.Z, radius, 4 * Math.PI * radius * radius,
                color, intensity, false, samples);
    }

    public Shape shape() { return shape; }
    public Vec3 center() { return center; }
    /** The unit normal of a rectangle or disc (for a sphere, +y: unused). */
    public Vec3 normal() { return normal; }
    /** Half the rectangle's width along its tangent, or the disc's radius along one in-plane axis. */
    public Vec3 halfU() { return u; }
    /** Half the rectangle's height along normal x tangent, or the disc's radius along the other in-plane axis. */
    public Vec3 halfV() { return v; }
    /** The radius of a disc or sphere (0 for a rectangle). */
    public double radius() { return radius; }
    /** The emitting surface's area. */
    public double area() { return area; }
    public Color color() { return color; }
    public double intensity() { return intensity; }
    public boolean oneSided() { return oneSided; }
    public int samples() { return samples; }

    /**
     * The same light with the intensity that makes its emitted power (flux) {@code power}: power =
     * intensity * pi * area, times 2 for a rectangle or disc that emits from both faces. Power lets
     * a light be resized without changing how much light it gives.
     *
     * @param power the emitted power, per unit of colour, at least 0
     * @return the light with that power
     * @throws IllegalArgumentException if the resulting intensity is out of range
     */
    public AreaLight withPower(double power) {
        Ranges.inRange("area light power", power, Ranges.MAX_INTENSITY);
        double faces = shape != Shape.SPHERE && !oneSided ? 2 : 1;
        return new AreaLight(shape, center, normal, u, v, radius, area, color, power / (Math.PI * area * faces), oneSided, samples);
    }

    /**
     * Intensity times the largest colour component: what the lights' total ({@link Ranges#MAX_TOTAL_LIGHT}) adds up.
     *
     * @return the radiance bound
     */
    public double power() { return intensity * color.max(); }
}
