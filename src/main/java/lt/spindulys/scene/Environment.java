package lt.spindulys.scene;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

import lt.spindulys.math.Ranges;
import lt.spindulys.texture.TextureCache;
import lt.spindulys.texture.TextureImage;

/**
 * A background from a latitude-longitude (equirectangular) image: what a ray that hits nothing
 * sees, camera rays and reflected and refracted rays alike, in place of the settings' background
 * colour. By default it is not a light: it lights nothing but what mirrors and glass show of it.
 * Made {@link #isLight() a light}, it also lights diffuse and specular surfaces: each shaded point
 * sends {@link #samples()} shadow rays per pixel sample towards directions drawn in proportion to
 * the map's brightness ({@link EnvironmentLight}), and those that leave the scene bring the
 * radiance seen along them, as an area light's do (a white map of value L lights an open,
 * upward-facing diffuse point as an area light filling the sky with radiance L would: pi L).
 *
 * <p>Convention (up is +Y, the default camera up): the image's top row is straight up (+Y), its
 * bottom row straight down, its middle row the horizon; across, u = 0 (the left edge) looks
 * towards -Z, u = 0.25 towards +X, u = 0.5 (the centre) towards +Z, u = 0.75 towards -X. So the
 * default camera, at (0, 0, -5) looking along +Z, sees the image's centre ahead, with the image's
 * left on its left. For a unit direction d: {@code u = atan2(dx, -dz) / 2pi} (in [0, 1)),
 * {@code v = acos(dy) / pi} from the top.
 *
 * <p>{@code rotate} turns the map about the up axis by that many degrees, by the right-hand rule
 * (as an object's {@code rotate y} turns it): what was seen along d is seen along R_y(degrees) d.
 * {@code intensity} scales every value.
 *
 * <p>What camera rays see can differ from what lights the scene, as Blender's "ray visibility:
 * camera" does: {@link #withCameraView} hides the map from camera rays (they see the background
 * colour) or scales what they see by its own visible intensity; reflected and refracted rays and
 * the light's shadow rays still see the map at {@code intensity}. Lookups are bilinear between texel centres, wrapping
 * across the u = 0 seam and clamped at the poles' rows. Immutable and thread-safe.
 */
public final class Environment {
    /** Largest intensity; with texels at most {@link Ranges#MAX_COLOUR} every value stays finite. */
    public static final double MAX_INTENSITY = Ranges.MAX_COLOUR;

    private final TextureImage map;
    private final double rotateDegrees, intensity;
    private final boolean light;
    private final int samples;
    /** Whether camera rays see the map (else the settings' background colour), and at what intensity. */
    private final boolean background;
    private final double visibleIntensity;
    /** The rotation as a fraction of a turn, added to u. */
    private final double uShift;
    private final int w, h;

    /**
     * An environment showing {@code map}.
     *
     * @param map           the lat-long image (linear values)
     * @param rotateDegrees turn about the up axis, degrees (any finite value)
     * @param intensity     scale of every value, 0 to {@link #MAX_INTENSITY}
     * @throws IllegalArgumentException if the rotation is not finite or the intensity is out of range
     */
    public Environment(TextureImage map, double rotateDegrees, double intensity) {
        this(map, rotateDegrees, intensity, false, 1);
    }

    /**
     * An environment showing {@code map}, and if {@code light} lighting the scene with
     * {@code samples} shadow rays per shaded point and pixel sample.
     *
     * @param map           the lat-long image (linear values)
     * @param rotateDegrees turn about the up axis, degrees (any finite value)
     * @param intensity     scale of every value, 0 to {@link #MAX_INTENSITY}
     * @param light         whether it lights surfaces
     * @param samples       shadow rays per pixel sample when a light, 1..{@link AreaLight#MAX_SAMPLES}
     * @throws IllegalArgumentException if a value is out of range
     */
    public Environment(TextureImage map, double rotateDegrees, double intensity, boolean light, int samples) {
        this(map, rotateDegrees, intensity, light, samples, true, intensity);
    }

    private Environment(TextureImage map, double rotateDegrees, double intensity, boolean light, int samples, boolean background, double visibleIntensity) {
        this.background = background;
        this.visibleIntensity = visibleIntensity;
        if (samples < 1 || samples > AreaLight.MAX_SAMPLES) {
            throw new IllegalArgumentException("environment samples must be 1.." + AreaLight.MAX_SAMPLES + ", found " + samples);
        }
        this.light = light;
        this.samples = samples;
        this.map = Objects.requireNonNull(map);
        if (!Double.isFinite(rotateDegrees)) throw new IllegalArgumentException("environment rotate must be a finite number of degrees, found " + rotateDegrees);
        if (!(intensity >= 0 && intensity <= MAX_INTENSITY)) {
            throw new IllegalArgumentException("environment intensity must be between 0 and " + Ranges.show(MAX_INTENSITY) + ", found " + intensity);
        }
        // After intensity's check: by default the visible intensity is the intensity, reported as such.
        if (!(visibleIntensity >= 0 && visibleIntensity <= MAX_INTENSITY)) {
            throw new IllegalArgumentException("environment visibleintensity must be between 0 and " + Ranges.show(MAX_INTENSITY) + ", found " + visibleIntensity);
        }
        this.rotateDegrees = rotateDegrees;
        this.intensity = intensity;
        double turns = rotateDegrees / 360;
        this.uShift = turns - Math.floor(turns);
        this.w = map.width();
        this.h = map.height();
    }

    /**
     * An environment from an image file: OpenEXR {@code .exr}, Radiance {@code .hdr} and {@code .pfm} are linear, PNG
     * and JPEG colour images are sRGB-decoded, as textures are ({@link TextureCache}).
     *
     * @param file          the image
     * @param rotateDegrees turn about the up axis, degrees
     * @param intensity     scale of every value, 0 to {@link #MAX_INTENSITY}
     * @return the environment
     * @throws IOException "FILE: reason" if the image cannot be read
     */
    public static Environment load(Path file, double rotateDegrees, double intensity) throws IOException {
        return new Environment(new TextureCache().load(file), rotateDegrees, intensity);
    }

    /**
     * This environment as a light with {@code samples} shadow rays per shaded point and pixel
     * sample (or, with {@code samples} 0, as a background only).
     *
     * @param samples 1..{@link AreaLight#MAX_SAMPLES}, or 0 for no light
     * @return the environment with that setting
     * @throws IllegalArgumentException if samples is out of range
     */
    public Environment asLight(int samples) {
        return samples == 0 ? new Environment(map, rotateDegrees, intensity, false, 1, background, visibleIntensity)
                : new Environment(map, rotateDegrees, intensity, true, samples, background, visibleIntensity);
    }

    /**
     * This environment as camera rays see it: hidden from them (they see the settings' background
     * colour instead) or shown scaled by {@code visibleIntensity} in place of {@link #intensity()}.
     * Reflections, refractions and the light are not affected.
     *
     * @param background       whether camera rays see the map
     * @param visibleIntensity the scale of what camera rays see, 0 to {@link #MAX_INTENSITY}
     * @return the environment with that camera view
     * @throws IllegalArgumentException if the intensity is out of range
     */
    public Environment withCameraView(boolean background, double visibleIntensity) {
        return new Environment(map, rotateDegrees, intensity, light, light ? samples : 1, background, visibleIntensity);
    }

    /** Whether camera rays see the map (else the settings' background colour). @return true if they do */
    public boolean isBackground() { return background; }

    /** The scale of what camera rays see. @return the visible intensity, {@link #intensity()} unless set */
    public double visibleIntensity() { return visibleIntensity; }

    /**
     * What a camera ray sees along the UNIT direction d, written to out[0..2]: the map scaled by
     * {@link #visibleIntensity()}, or {@code background} if the map is hidden from camera rays.
     *
     * @param dx direction x
     * @param dy direction y
     * @param dz direction z
     * @param background the settings' background colour
     * @param out receives r, g, b
     */
    public void lookupFromCamera(double dx, double dy, double dz, lt.spindulys.math.Color background, double[] out) {
        if (!this.background) {
            out[0] = background.r(); out[1] = background.g(); out[2] = background.b();
            return;
        }
        double u = atan2(dx, -dz) * (0.5 / Math.PI) + uShift;
        double v = atan2(Math.sqrt(dx * dx + dz * dz), dy) * (1 / Math.PI);
        lookupImage(u, v, out, 0, visibleIntensity);
    }

    /** The image. @return the map */
    public TextureImage map() { return map; }

    /** The turn about the up axis. @return degrees, as given */
    public double rotateDegrees() { return rotateDegrees; }

    /** The scale of every value. @return the intensity */
    public double intensity() { return intensity; }

    /** Whether it lights surfaces (else it is only seen). @return true for a light */
    public boolean isLight() { return light; }

    /** Shadow rays per shaded point and pixel sample when it is a light. @return 1..{@link AreaLight#MAX_SAMPLES} */
    public int samples() { return samples; }

    /** The rotation as a fraction of a turn in [0, 1), added to a direction's u. */
    double uShift() { return uShift; }

    /**
     * atan2(y, x) in [-pi, pi], within 1e-7 radians (a hundred-thousandth of a texel of a
     * 4096-wide map). Math.atan2 and Math.acos are fdlibm's, about 60 ns each, most of a lookup's
     * time; this is an octant reduction to |t| <= tan(pi/8) and the odd Taylor series of atan up
     * to t^15 (remainder below 0.4143^17 / 17 = 2e-8).
     */
    static double atan2(double y, double x) {
        double ax = Math.abs(x), ay = Math.abs(y);
        double hi = Math.max(ax, ay), lo = Math.min(ax, ay);
        if (hi == 0) return 0;
        double a = lo / hi, base = 0;  // a in [0, 1]
        if (a > 0.41421356237309503) {  // tan(pi/8): atan(a) = pi/4 + atan((a - 1) / (a + 1))
            a = (a - 1) / (a + 1);
            base = Math.PI / 4;
        }
        double t2 = a * a;
        double p = 1.0 / 15;
        p = p * t2 - 1.0 / 13;
        p = p * t2 + 1.0 / 11;
        p = p * t2 - 1.0 / 9;
        p = p * t2 + 1.0 / 7;
        p = p * t2 - 1.0 / 5;
        p = p * t2 + 1.0 / 3;
        double r = base + a - a * t2 * p;  // atan(a) = a - a^3/3 + a^5/5 - ...
        if (ay > ax) r = Math.PI / 2 - r;
        if (x < 0) r = Math.PI - r;
        return y < 0 ? -r : r;
    }

    /**
     * The value seen along the UNIT direction d, written to out[0..2].
     *
     * @param dx direction x
     * @param dy direction y
     * @param dz direction z
     * @param out receives r, g, b
     */
    public void lookup(double dx, double dy, double dz, double[] out) {
        double u = atan2(dx, -dz) * (0.5 / Math.PI) + uShift;  // in (-0.5, 1.5)
        double v = atan2(Math.sqrt(dx * dx + dz * dz), dy) * (1 / Math.PI);  // acos(dy) for unit d
        lookupImage(u, v, out, 0);
    }

    /**
     * The value at image coordinates (u, v) (u wraps; v in [0, 1] from the top), written to
     * out[at..at+2]: the blend that {@link #lookup} makes for the direction there.
     */
    void lookupImage(double u, double v, double[] out, int at) { lookupImage(u, v, out, at, intensity); }

    private void lookupImage(double u, double v, double[] out, int at, double scale) {
        double fx = u * w - 0.5, fy = v * h - 0.5;
        double x0f = Math.floor(fx);
        double tx = fx - x0f;
        int x0 = Math.floorMod((int) x0f, w), x1 = x0 + 1 == w ? 0 : x0 + 1;
        fy = Math.max(0, Math.min(h - 1, fy));
        int y0 = (int) fy, y1 = Math.min(y0 + 1, h - 1);
        double ty = fy - y0;
        for (int c = 0; c < 3; c++) {
            double top = map.texel(0, x0, y0, c) * (1 - tx) + map.texel(0, x1, y0, c) * tx;
            double bottom = map.texel(0, x0, y1, c) * (1 - tx) + map.texel(0, x1, y1, c) * tx;
            out[at + c] = scale * (top * (1 - ty) + bottom * ty);
        }
    }
}
