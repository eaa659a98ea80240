package lt.spindulys.scene;

import lt.spindulys.math.Color;

/**
 * Surface and medium properties of the thesis's Whitted model, immutable.
 * <ul>
 * <li>local: ambient ka*Ia*C, diffuse kd*C*Ii*max(0, n.l), Blinn-Phong specular ks*Ii*(n.h)^shininess;</li>
 * <li>secondary: reflection weighted by kr, refraction by kt*filter with index of refraction ior;</li>
 * <li>medium: light travelling a distance d inside is attenuated by e^(-beta*d) per channel;</li>
 * <li>fresnel: Schlick's approximation moves the reflected share of kt into reflection.</li>
 * </ul>
 * Build with {@link #builder()}; every setter validates its value.
 */
public final class Material {
    /** The material of objects that name none. */
    public static final Material DEFAULT = builder().name("default").build();

    private final String name;
    private final Color color, filter, beta;
    private final double ka, kd, ks, shininess, kr, kt, ior;
    private final boolean fresnel;

    private Material(Builder b) {
        name = b.name; color = b.color; filter = b.filter; beta = b.beta;
        ka = b.ka; kd = b.kd; ks = b.ks; shininess = b.shininess; kr = b.kr; kt = b.kt; ior = b.ior; fresnel = b.fresnel;
    }

    public static Builder builder() { return new Builder(); }

    /** A builder initialised from this material, to derive a variant. */
    public Builder toBuilder() {
        Builder b = new Builder();
        b.name = name; b.color = color; b.filter = filter; b.beta = beta;
        b.ka = ka; b.kd = kd; b.ks = ks; b.shininess = shininess; b.kr = kr; b.kt = kt; b.ior = ior; b.fresnel = fresnel;
        return b;
    }

    public String name() { return name; }
    /** Surface colour C. */
    public Color color() { return color; }
    /** Colour that tints transmitted light (refraction and shadows through the object). */
    public Color filter() { return filter; }
    /** Attenuation coefficient per unit distance inside the medium, per channel. */
    public Color beta() { return beta; }
    public double ka() { return ka; }
    public double kd() { return kd; }
    public double ks() { return ks; }
    public double shininess() { return shininess; }
    public double kr() { return kr; }
    public double kt() { return kt; }
    public double ior() { return ior; }
    public boolean fresnel() { return fresnel; }
    public boolean isTransparent() { return kt > 0; }
    public boolean attenuates() { return !beta.isBlack(); }

    @Override public String toString() { return "Material[" + (name == null ? "unnamed" : name) + "]"; }

    /** Validating builder; each setter throws IllegalArgumentException naming the value expected. */
    public static final class Builder {
        private String name;
        private Color color = Color.grey(0.8), filter = Color.WHITE, beta = Color.BLACK;
        private double ka = 0.1, kd = 0.9, ks = 0, shininess = 20, kr = 0, kt = 0, ior = 1;
        private boolean fresnel;

        public Builder name(String v) { name = v; return this; }
        public Builder color(Color v) { color = colour("color", v); return this; }
        public Builder filter(Color v) { filter = colour("filter", v); return this; }
        public Builder beta(Color v) { beta = colour("beta", v); return this; }
        public Builder beta(double v) { return beta(Color.grey(v)); }
        public Builder ka(double v) { ka = nonNegative("ka", v); return this; }
        public Builder kd(double v) { kd = nonNegative("kd", v); return this; }
        public Builder ks(double v) { ks = nonNegative("ks", v); return this; }
        public Builder shininess(double v) { shininess = nonNegative("shininess", v); return this; }
        public Builder kr(double v) { kr = nonNegative("kr", v); return this; }
        public Builder kt(double v) { kt = nonNegative("kt", v); return this; }
        public Builder fresnel(boolean v) { fresnel = v; return this; }

        public Builder ior(double v) {
            if (!(v > 0) || !Double.isFinite(v)) throw new IllegalArgumentException("ior must be a positive number, found " + v);
            ior = v;
            return this;
        }

        public Material build() { return new Material(this); }

        private static double nonNegative(String what, double v) {
            if (!(v >= 0) || !Double.isFinite(v)) throw new IllegalArgumentException(what + " must be a non-negative number, found " + v);
            return v;
        }

        private static Color colour(String what, Color c) {
            if (!c.isFinite() || !c.isNonNegative()) throw new IllegalArgumentException(what + " must have non-negative finite components, found " + c);
            return c;
        }
    }
}
