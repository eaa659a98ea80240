package lt.spindulys.material;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Mapping;
import lt.spindulys.texture.Texture;

/**
 * Surface and medium properties, immutable, of one of two {@linkplain Model models}.
 *
 * <p>{@link Model#WHITTED} (the default) is the thesis's model:
 * <ul>
 * <li>local: ambient ka*Ia*C, diffuse kd*C*Ii*max(0, n.l), Blinn-Phong specular ks*Ii*(n.h)^shininess;</li>
 * <li>secondary: reflection weighted by kr, refraction by kt*filter with index of refraction ior;</li>
 * <li>medium: light travelling a distance d inside is attenuated by e^(-beta*d) per channel;</li>
 * <li>fresnel: Schlick's approximation moves the reflected share of kt into reflection.</li>
 * </ul>
 *
 * <p>{@link Model#PRINCIPLED} describes the surface physically, as the path integrator's
 * principled BSDF takes it: base colour C (color, a reflectance in [0, 1]), metallic,
 * roughness and transmission (each in [0, 1]) and ior (default 1.5). So that such a material also
 * renders under the Whitted integrator, its Whitted getters return terms derived from those
 * values, with F0 = ((ior - 1) / (ior + 1))^2 the reflectance of a dielectric surface at normal
 * incidence, alpha = roughness^2 the GGX width, M = min(1, mean of C) a metal's mean reflectance,
 * m = metallic, r = roughness, t = transmission:
 * <ul>
 * <li>color = C; filter = the given filter times C (glass is tinted by its base colour);</li>
 * <li>kd = (1 - m)(1 - t) + m r: the diffuse base, plus the blurred part of a rough metal, shown
 *     as diffuse light of its colour (Whitted reflections and highlights are untinted, so this is
 *     where a metal's colour shows); ka = 0.1 kd;</li>
 * <li>shininess = 2 / alpha^2 - 2, at most 1e6: the Blinn-Phong exponent whose lobe has GGX's
 *     width (alpha = sqrt(2 / (n + 2)), as {@code WhittedMaterialBsdf} maps it back);</li>
 * <li>ks = S / (4 alpha^2), at most 10, with S = m M + (1 - m) F0: the peak of the GGX highlight
 *     of a light (F D(0) / 4 with D(0) = 1 / (pi alpha^2), times pi as Whitted's kd = 1 is the
 *     Lambert albedo 1); 0 when S is 0;</li>
 * <li>kr = (1 - r)(m M + (1 - m)(1 - t) F0): the mirror share of smooth metal and of the
 *     dielectric coat, fading with roughness (Whitted's mirror is sharp);</li>
 * <li>kt = (1 - m) t, with fresnel on when kt is above 0: glass reflects by Schlick's term from
 *     kt, as a Whitted glass with fresnel does.</li>
 * </ul>
 * So kr + kt is at most m + (1 - m)(1 - t) + (1 - m) t = 1, and every term is in its Whitted
 * range. Whitted keys (ka, kd, ks, shininess, kr, kt, fresnel) and the specular and reflection
 * texture channels belong to the Whitted model; metallic, roughness, transmission and the
 * roughness and metallic channels to the principled one ({@link Model#refusal(String)}). Color,
 * ior, beta, filter, emission and the other channels apply to both. Emission is light the surface
 * gives off, in either model, added to an emission texture's colour.
 *
 * <p>Any channel may be driven by a texture through a mapping ({@link Builder#texture}): the
 * integrator evaluates the bound channels at each hit (see {@link Channel} for what each does).
 * Build with {@link #builder()}; every setter validates its value against the ranges that keep
 * every pixel finite ({@link Ranges}): color and emission 0..100 (color 0..1 for a principled
 * material), ka, kd, ks 0..10, shininess 0..1e6, kr, kt and filter 0..1 with kr + kt at most 1,
 * metallic, roughness and transmission 0..1, beta 0..1e15. Which keys were given is checked
 * against the model when the material is built, so the order of the setters does not matter.
 */
public final class Material {
    /** The material of objects that name none. */
    public static final Material DEFAULT = builder().name("default").build();

    /**
     * Which description of the surface a material gives: the thesis's Whitted coefficients, or the
     * physically based parameters of the path integrator's principled BSDF (see {@link Material}
     * for how the Whitted integrator renders the latter). Scene keyword: the lower-case name.
     */
    public enum Model {
        /** ka, kd, ks, shininess, kr, kt, fresnel; the default. */
        WHITTED(List.of("ka", "kd", "ks", "shininess", "kr", "kt", "fresnel"), Channel.SPECULAR, Channel.REFLECTION),
        /** metallic, roughness, transmission (ior defaults to 1.5). */
        PRINCIPLED(List.of("metallic", "roughness", "transmission"), Channel.ROUGHNESS, Channel.METALLIC);

        private final List<String> ownKeys;
        private final Set<Channel> ownChannels;

        Model(List<String> ownKeys, Channel... ownChannels) {
            this.ownKeys = ownKeys;
            this.ownChannels = Set.of(ownChannels);
        }

        /**
         * The scene-language word: the lower-case name.
         *
         * @return the keyword
         */
        public String keyword() { return name().toLowerCase(Locale.ROOT); }

        /**
         * The model with this scene-language word.
         *
         * @param word the keyword
         * @return the model
         * @throws IllegalArgumentException if no model has that word
         */
        public static Model fromKeyword(String word) {
            for (Model m : values()) if (m.keyword().equals(word)) return m;
            throw new IllegalArgumentException("unknown material model '" + word + "'");
        }

        /**
         * Every scene-language word, in declaration order.
         *
         * @return the keywords
         */
        public static List<String> keywords() {
            List<String> out = new ArrayList<>();
            for (Model m : values()) out.add(m.keyword());
            return List.copyOf(out);
        }

        /**
         * The keys (as the scene language and the builder's messages spell them) that only this
         * model takes.
         *
         * @return the keys, in documentation order
         */
        public List<String> ownKeys() { return ownKeys; }

        /**
         * Whether a texture channel drives a term only this model has.
         *
         * @param c the channel
         * @return whether only this model takes it
         */
        public boolean owns(Channel c) { return ownChannels.contains(c); }

        /**
         * Why a material of this model cannot take a key, or null if it can (the key is this
         * model's own, or applies to both, or is not a material key at all).
         *
         * @param key a key as the scene language spells it
         * @return the one-line refusal naming the key and the model it belongs to, or null
         */
        public String refusal(String key) {
            for (Model other : values()) {
                if (other != this && other.ownKeys.contains(key)) return refusal("'" + key + "'", other);
            }
            return null;
        }

        /**
         * Why a material of this model cannot bind a texture to a channel, or null if it can.
         *
         * @param c the channel
         * @return the one-line refusal naming the channel and the model it belongs to, or null
         */
        public String refusal(Channel c) {
            for (Model other : values()) {
                if (other != this && other.owns(c)) return refusal("channel " + c.keyword(), other);
            }
            return null;
        }

        private String refusal(String what, Model owner) {
            return what + " belongs to model " + owner.keyword() + ", not to a model " + keyword() + " material"
                    // Whitted is the default, so a principled key most likely lacks its 'model principled'.
                    + (this == WHITTED ? " (a material is whitted unless it gives 'model principled')" : "");
        }
    }

    /** Rule of thumb in the derived terms: the ambient coefficient is this share of the diffuse one (Whitted's default ka 0.1). */
    private static final double AMBIENT_SHARE = 0.1;

    private final String name;
    private final Model model;
    private final Color color, filter, beta, emission;
    /** The filter as given (a principled material's {@link #filter()} is tinted by its colour). */
    private final Color givenFilter;
    private final double ka, kd, ks, shininess, kr, kt, ior;
    private final double metallic, roughness, transmission;
    private final boolean fresnel;
    /** The model-specific keys and ior the builder was given (for {@link #toBuilder()}). */
    private final List<String> given;
    private final Texture[] textures;
    private final Mapping[] mappings;
    private final double bumpStrength;
    private final boolean textured;

    private Material(Builder b) {
        name = b.name; model = b.model; color = b.color; beta = b.beta; emission = b.emission; givenFilter = b.filter;
        metallic = b.metallic; roughness = b.roughness; transmission = b.transmission;
        given = List.copyOf(b.given);
        textures = b.textures.clone(); mappings = b.mappings.clone(); bumpStrength = b.bumpStrength;
        boolean any = false;
        for (Texture t : textures) any |= t != null;
        textured = any;
        if (model == Model.WHITTED) {
            filter = b.filter;
            ka = b.ka; kd = b.kd; ks = b.ks; shininess = b.shininess; kr = b.kr; kt = b.kt; fresnel = b.fresnel;
            ior = Double.isNaN(b.ior) ? 1 : b.ior;
            return;
        }
        // The derived Whitted terms; the class comment gives the rule and why.
        ior = Double.isNaN(b.ior) ? 1.5 : b.ior;
        double m = metallic, r = roughness, t = transmission;
        double f0 = (ior - 1) / (ior + 1);
        f0 *= f0;
        double metal = Math.min(1, (color.r() + color.g() + color.b()) / 3);
        double alpha2 = r * r * r * r;
        filter = new Color(b.filter.r() * color.r(), b.filter.g() * color.g(), b.filter.b() * color.b());
        kd = (1 - m) * (1 - t) + m * r;
        ka = AMBIENT_SHARE * kd;
        shininess = Math.min(Ranges.MAX_SHININESS, 2 / alpha2 - 2);
        double highlight = m * metal + (1 - m) * f0;
        ks = highlight > 0 ? Math.min(Ranges.MAX_COEFFICIENT, highlight / (4 * alpha2)) : 0;
        kt = (1 - m) * t;
        // At most 1 - kt already (see the class comment); the min only guards the last bit.
        kr = Math.min(1 - kt, (1 - r) * (m * metal + (1 - m) * (1 - t) * f0));
        fresnel = kt > 0;
    }

    /** {@return a builder with the defaults: Whitted, grey 0.8, ka 0.1, kd 0.9, no specular, reflection, transmission or emission, ior 1 (1.5 once the model is principled)} */
    public static Builder builder() { return new Builder(); }

    /**
     * A builder initialised from this material, to derive a variant: the values given to this
     * material's builder, not a principled material's derived Whitted terms, and its ior only if
     * it was given (else the model's default again).
     *
     * @return the builder; changing it leaves this material as it is
     */
    public Builder toBuilder() {
        Builder b = new Builder();
        b.name = name; b.model = model; b.color = color; b.beta = beta; b.emission = emission;
        b.metallic = metallic; b.roughness = roughness; b.transmission = transmission;
        b.given.addAll(given);
        b.filter = givenFilter;
        if (model == Model.WHITTED) {
            b.ka = ka; b.kd = kd; b.ks = ks; b.shininess = shininess; b.kr = kr; b.kt = kt; b.fresnel = fresnel;
        }
        b.ior = given.contains("ior") ? ior : Double.NaN;
        b.textures = textures.clone(); b.mappings = mappings.clone(); b.bumpStrength = bumpStrength;
        return b;
    }

    /** {@return the name given in the scene, or null} */
    public String name() { return name; }
    /** {@return the model the material is described in} */
    public Model model() { return model; }
    /**
     * Surface colour C; a principled material's base colour.
     *
     * @return the colour, linear RGB
     */
    public Color color() { return color; }
    /**
     * Colour that tints transmitted light (refraction and shadows through the object); for a
     * principled material the given filter times the base colour.
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
    // For a principled material the Whitted terms below are derived (see the class comment).
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
    /** {@return the metal fraction of a principled material, in [0, 1]; 0 for a Whitted one} */
    public double metallic() { return metallic; }
    /** {@return the perceptual roughness of a principled material, in [0, 1] (GGX alpha is its square); 0.5 for a Whitted one} */
    public double roughness() { return roughness; }
    /** {@return the glass fraction of a principled material's non-metal part, in [0, 1]; 0 for a Whitted one} */
    public double transmission() { return transmission; }
    /**
     * Light the surface gives off (radiance, linear RGB), in either model; an emission texture's
     * colour is added to it.
     *
     * @return the emitted colour, components 0..100; black for none
     */
    public Color emission() { return emission; }
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

    /**
     * Validating builder; each setter throws IllegalArgumentException naming the value expected,
     * and {@link #build()} checks what depends on the model (which keys it takes, the principled
     * colour's range), so setters may come in any order.
     */
    public static final class Builder {
        private String name;
        private Model model = Model.WHITTED;
        private Color color = Color.grey(0.8), filter = Color.WHITE, beta = Color.BLACK, emission = Color.BLACK;
        private double ka = 0.1, kd = 0.9, ks = 0, shininess = 20, kr = 0, kt = 0;
        private double metallic = 0, roughness = 0.5, transmission = 0;
        /** NaN until given: the model's default (1 Whitted, 1.5 principled) is chosen when the material is built. */
        private double ior = Double.NaN;
        private boolean fresnel;
        /** The model-specific keys set, and ior, in the order first set: checked against the model by build(). */
        private final Set<String> given = new LinkedHashSet<>();
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
        /**
         * Sets the model (default {@link Model#WHITTED}).
         *
         * @param v the model
         * @return this builder
         */
        public Builder model(Model v) {
            if (v == null) throw new IllegalArgumentException("material model is missing");
            model = v;
            return this;
        }
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
        public Builder ka(double v) { ka = Ranges.inRange("ka", v, Ranges.MAX_COEFFICIENT); given.add("ka"); return this; }
        /**
         * Sets the diffuse coefficient.
         *
         * @param v 0..10
         * @return this builder
         */
        public Builder kd(double v) { kd = Ranges.inRange("kd", v, Ranges.MAX_COEFFICIENT); given.add("kd"); return this; }
        /**
         * Sets the specular coefficient.
         *
         * @param v 0..10
         * @return this builder
         */
        public Builder ks(double v) { ks = Ranges.inRange("ks", v, Ranges.MAX_COEFFICIENT); given.add("ks"); return this; }
        /**
         * Sets the Blinn-Phong exponent.
         *
         * @param v 0..1e6; larger is a smaller, sharper highlight
         * @return this builder
         */
        public Builder shininess(double v) { shininess = Ranges.inRange("shininess", v, Ranges.MAX_SHININESS); given.add("shininess"); return this; }
        /**
         * Sets the share reflected.
         *
         * @param v 0..1, with kr + kt at most 1
         * @return this builder
         */
        public Builder kr(double v) { kr = Ranges.inRange("kr", v, 1); given.add("kr"); return this; }
        /**
         * Sets the share transmitted.
         *
         * @param v 0..1, with kr + kt at most 1
         * @return this builder
         */
        public Builder kt(double v) { kt = Ranges.inRange("kt", v, 1); given.add("kt"); return this; }
        /**
         * Turns Schlick's Fresnel term on or off (default off).
         *
         * @param v whether to use it
         * @return this builder
         */
        public Builder fresnel(boolean v) { fresnel = v; given.add("fresnel"); return this; }
        /**
         * Sets a principled material's metal fraction (default 0).
         *
         * @param v 0..1
         * @return this builder
         */
        public Builder metallic(double v) { metallic = Ranges.inRange("metallic", v, 1); given.add("metallic"); return this; }
        /**
         * Sets a principled material's perceptual roughness (default 0.5): 0 is a mirror, the
         * GGX width alpha is its square.
         *
         * @param v 0..1
         * @return this builder
         */
        public Builder roughness(double v) { roughness = Ranges.inRange("roughness", v, 1); given.add("roughness"); return this; }
        /**
         * Sets a principled material's glass fraction of its non-metal part (default 0).
         *
         * @param v 0..1
         * @return this builder
         */
        public Builder transmission(double v) { transmission = Ranges.inRange("transmission", v, 1); given.add("transmission"); return this; }
        /**
         * Sets the light the surface gives off, in either model (default black).
         *
         * @param v linear RGB radiance, components 0..100
         * @return this builder
         */
        public Builder emission(Color v) { emission = Ranges.colour("emission", v, Ranges.MAX_COLOUR); return this; }

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
         * Sets the index of refraction of the medium inside (default 1, air, for a Whitted
         * material; 1.5, glass or plastic, for a principled one).
         *
         * @param v above 0, at most 1e15
         * @return this builder
         */
        public Builder ior(double v) {
            if (!(v > 0) || !Ranges.isModest(v)) throw new IllegalArgumentException("ior must be a positive number at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + v);
            ior = v;
            given.add("ior");
            return this;
        }

        /**
         * The material.
         *
         * @return the material
         * @throws IllegalArgumentException if a key or texture channel given belongs to the
         *         other model ({@link Model#refusal(String)}, the first in the order set), if a
         *         principled colour exceeds 1 (a base colour is a reflectance: more would make
         *         light), or if kr + kt exceeds 1: what a surface reflects and transmits together
         *         cannot exceed what arrives (it would also let a path of many surfaces grow
         *         without bound)
         */
        public Material build() {
            for (String key : given) {
                String refusal = model.refusal(key);
                if (refusal != null) throw new IllegalArgumentException(refusal);
            }
            for (Channel c : Channel.values()) {
                String refusal = textures[c.ordinal()] != null ? model.refusal(c) : null;
                if (refusal != null) throw new IllegalArgumentException(refusal);
            }
            if (model == Model.PRINCIPLED) Ranges.colour("color of a principled material", color, 1);
            if (kr + kt > 1 + KR_KT_SLACK) throw new IllegalArgumentException("kr + kt must be at most 1, found kr " + kr + " + kt " + kt + " = " + (kr + kt));
            return new Material(this);
        }

        /** Rounding in decimal fractions that add up to 1 (0.7 + 0.3) is not an excess. */
        private static final double KR_KT_SLACK = 1e-9;
    }
}
