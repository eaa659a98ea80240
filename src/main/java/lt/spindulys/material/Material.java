package lt.spindulys.material;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Mapping;
import lt.spindulys.texture.Texture;

/**
 * Surface and medium properties of the thesis's Whitted model, immutable.
 * <ul>
 * <li>local: ambient ka*Ia*C, diffuse kd*C*Ii*max(0, n.l), Blinn-Phong specular ks*Ii*(n.h)^shininess;</li>
 * <li>secondary: reflection weighted by kr, refraction by kt*filter with index of refraction ior;</li>
 * <li>medium: light travelling a distance d inside is attenuated by e^(-beta*d) per channel;</li>
 * <li>fresnel: Schlick's approximation moves the reflected share of kt into reflection.</li>
 * </ul>
 * Any channel may be driven by a texture through a mapping ({@link Builder#texture}): the
 * integrator evaluates the bound channels at each hit (see {@link Channel} for what each does).
 * Build with {@link #builder()}; every setter validates its value against the ranges that keep
 * every pixel finite ({@link Ranges}): color 0..100, ka, kd, ks 0..10, shininess 0..1e6, kr, kt
 * and filter 0..1 with kr + kt at most 1, beta 0..1e15.
 */
public final class Material {
    /** The material of objects that name none. */
    public static final Material DEFAULT = builder().name("default").build();

    private final String name;
    private final Color color, filter, beta;
    private final double ka, kd, ks, shininess, kr, kt, ior;
    private final boolean fresnel;
    private final Texture[] textures;
    private final Mapping[] mappings;
    private final double bumpStrength;
    private final boolean textured;

    private Material(Builder b) {
        name = b.name; color = b.color; filter = b.filter; beta = b.beta;
        ka = b.ka; kd = b.kd; ks = b.ks; shininess = b.shininess; kr = b.kr; kt = b.kt; ior = b.ior; fresnel = b.fresnel;
        textures = b.textures.clone(); mappings = b.mappings.clone(); bumpStrength = b.bumpStrength;
        boolean any = false;
        for (Texture t : textures) any |= t != null;
        textured = any;
    }

    /** {@return a builder with the defaults: grey 0.8, ka 0.1, kd 0.9, no specular, reflection or transmission, ior 1} */
    public static Builder builder() { return new Builder(); }

    /**
     * A builder initialised from this material, to derive a variant.
     *
     * @return the builder; changing it leaves this material as it is
     */
    public Builder toBuilder() {
        Builder b = new Builder();
        b.name = name; b.color = color; b.filter = filter; b.beta = beta;
        b.ka = ka; b.kd = kd; b.ks = ks; b.shininess = shininess; b.kr = kr; b.kt = kt; b.ior = ior; b.fresnel = fresnel;
        b.textures = textures.clone(); b.mappings = mappings.clone(); b.bumpStrength = bumpStrength;
        return b;
    }

    /** {@return the name given in the scene, or null} */
    public String name() { return name; }
    /**
     * Surface colour C.
     *
     * @return the colour, linear RGB
     */
    public Color color() { return color; }
    /**
     * Colour that tints transmitted light (refraction and shadows through the object).
     *
     * @return the transmission filter, components in [0, 1]
     */
    public Color filter() { return filter; }
    /**
     * Attenuation coefficient per unit distance inside the medium, per channel.
     *
     * @return the coefficients, per unit of scene distance
     */
    public Color beta() { return beta; }
    /** {@return the ambient coefficient} */
    public double ka() { return ka; }
    /** {@return the diffuse coefficient} */
    public double kd() { return kd; }
    /** {@return the specular coefficient} */
    public double ks() { return ks; }
    /** {@return the Blinn-Phong exponent of the specular highlight} */
    public double shininess() { return shininess; }
    /** {@return the share of light reflected, in [0, 1]} */
    public double kr() { return kr; }
    /** {@return the share of light transmitted, in [0, 1]} */
    public double kt() { return kt; }
    /** {@return the index of refraction of the medium inside} */
    public double ior() { return ior; }
    /** {@return whether Schlick's Fresnel term shifts transmitted light into reflection} */
    public boolean fresnel() { return fresnel; }
    /** {@return whether light passes through the surface (kt above 0)} */
    public boolean isTransparent() { return kt > 0; }
    /**
     * The texture bound to a channel, or null.
     *
     * @param c the channel
     * @return the texture, or null
     */
    public Texture texture(Channel c) { return textures[c.ordinal()]; }
    /**
     * The mapping of the texture bound to a channel, or null.
     *
     * @param c the channel
     * @return the mapping, or null
     */
    public Mapping mapping(Channel c) { return mappings[c.ordinal()]; }
    /**
     * True if any channel has a texture.
     *
     * @return whether any channel has a texture
     */
    public boolean isTextured() { return textured; }
    /**
     * Object-space height of a bump texture's value 1 (the bump channel's texture is scaled by it).
     *
     * @return the height, object-space units
     */
    public double bumpStrength() { return bumpStrength; }
    /** {@return whether light is attenuated inside the medium (beta not black)} */
    public boolean attenuates() { return !beta.isBlack(); }

    @Override public String toString() { return "Material[" + (name == null ? "unnamed" : name) + "]"; }

    /** Validating builder; each setter throws IllegalArgumentException naming the value expected. */
    public static final class Builder {
        private String name;
        private Color color = Color.grey(0.8), filter = Color.WHITE, beta = Color.BLACK;
        private double ka = 0.1, kd = 0.9, ks = 0, shininess = 20, kr = 0, kt = 0, ior = 1;
        private boolean fresnel;
        private Texture[] textures = new Texture[Channel.values().length];
        private Mapping[] mappings = new Mapping[Channel.values().length];
        private double bumpStrength = 1;

        /** Only through {@link Material#builder()} and {@link Material#toBuilder()}. */
        Builder() {}

        /**
         * Names the material, for messages.
         *
         * @param v the name, or null
         * @return this builder
         */
        public Builder name(String v) { name = v; return this; }
        // The ranges keep every pixel finite (see Ranges): colours and ka, kd, ks bounded; kr, kt
        // and filter fractions, so that secondary rays never carry more than arrives.
        /**
         * Sets the surface colour C.
         *
         * @param v linear RGB, components 0..100
         * @return this builder
         */
        public Builder color(Color v) { color = Ranges.colour("color", v, Ranges.MAX_COLOUR); return this; }
        /**
         * Sets the colour that tints transmitted light.
         *
         * @param v components 0..1
         * @return this builder
         */
        public Builder filter(Color v) { filter = Ranges.colour("filter", v, 1); return this; }
        /**
         * Sets the attenuation inside the medium, per channel.
         *
         * @param v coefficients per unit of distance, 0..1e15
         * @return this builder
         */
        public Builder beta(Color v) { beta = Ranges.colour("beta", v, Ranges.MAX_NUMBER); return this; }
        /**
         * Sets the same attenuation on every channel.
         *
         * @param v coefficient per unit of distance, 0..1e15
         * @return this builder
         */
        public Builder beta(double v) { return beta(Color.grey(v)); }
        /**
         * Sets the ambient coefficient.
         *
         * @param v 0..10
         * @return this builder
         */
        public Builder ka(double v) { ka = Ranges.inRange("ka", v, Ranges.MAX_COEFFICIENT); return this; }
        /**
         * Sets the diffuse coefficient.
         *
         * @param v 0..10
         * @return this builder
         */
        public Builder kd(double v) { kd = Ranges.inRange("kd", v, Ranges.MAX_COEFFICIENT); return this; }
        /**
         * Sets the specular coefficient.
         *
         * @param v 0..10
         * @return this builder
         */
        public Builder ks(double v) { ks = Ranges.inRange("ks", v, Ranges.MAX_COEFFICIENT); return this; }
        /**
         * Sets the Blinn-Phong exponent.
         *
         * @param v 0..1e6; larger is a smaller, sharper highlight
         * @return this builder
         */
        public Builder shininess(double v) { shininess = Ranges.inRange("shininess", v, Ranges.MAX_SHININESS); return this; }
        /**
         * Sets the share reflected.
         *
         * @param v 0..1, with kr + kt at most 1
         * @return this builder
         */
        public Builder kr(double v) { kr = Ranges.inRange("kr", v, 1); return this; }
        /**
         * Sets the share transmitted.
         *
         * @param v 0..1, with kr + kt at most 1
         * @return this builder
         */
        public Builder kt(double v) { kt = Ranges.inRange("kt", v, 1); return this; }
        /**
         * Turns Schlick's Fresnel term on or off (default off).
         *
         * @param v whether to use it
         * @return this builder
         */
        public Builder fresnel(boolean v) { fresnel = v; return this; }

        /**
         * Binds a texture, evaluated through a mapping, to a channel; each channel takes at most
         * one texture.
         *
         * @param channel the channel it drives
         * @param texture the texture
         * @param mapping how a surface point becomes texture coordinates
         * @return this builder
         */
        public Builder texture(Channel channel, Texture texture, Mapping mapping) {
            if (channel == null || texture == null || mapping == null) throw new IllegalArgumentException("texture channel, texture and mapping must all be given");
            if (textures[channel.ordinal()] != null) throw new IllegalArgumentException("channel " + channel.keyword() + " already has a texture");
            textures[channel.ordinal()] = texture;
            mappings[channel.ordinal()] = mapping;
            return this;
        }

        /**
         * Scales the bump channel's height (object-space units per texture value 1); default 1.
         *
         * @param v the height per texture value 1; finite, at most 1e15 in magnitude, negative inverts
         * @return this builder
         */
        public Builder bumpStrength(double v) {
            if (!Ranges.isModest(v)) throw new IllegalArgumentException("bump strength must be a finite number at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude, found " + v);
            bumpStrength = v;
            return this;
        }

        /**
         * Sets the index of refraction of the medium inside (default 1, air).
         *
         * @param v above 0, at most 1e15
         * @return this builder
         */
        public Builder ior(double v) {
            if (!(v > 0) || !Ranges.isModest(v)) throw new IllegalArgumentException("ior must be a positive number at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + v);
            ior = v;
            return this;
        }

        /**
         * The material.
         *
         * @return the material
         * @throws IllegalArgumentException if kr + kt exceeds 1: what a surface reflects and
         *         transmits together cannot exceed what arrives (it would also let a path of
         *         many surfaces grow without bound)
         */
        public Material build() {
            if (kr + kt > 1 + KR_KT_SLACK) throw new IllegalArgumentException("kr + kt must be at most 1, found kr " + kr + " + kt " + kt + " = " + (kr + kt));
            return new Material(this);
        }

        /** Rounding in decimal fractions that add up to 1 (0.7 + 0.3) is not an excess. */
        private static final double KR_KT_SLACK = 1e-9;
    }
}
