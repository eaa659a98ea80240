package lt.spindulys.texture;

/**
 * The material channels a texture can drive (see docs/scene-format.md, "Textures"). A colour
 * texture's value is used as a colour by DIFFUSE and EMISSION, and as its mean (a scalar) by the
 * others. SPECULAR and REFLECTION drive terms only a Whitted material has, ROUGHNESS and METALLIC
 * terms only a principled one has; the rest apply to both.
 */
public enum Channel {
    /** Multiplies the material's colour C (ambient and diffuse; a principled material's base colour, clamped to [0, 1]). */
    DIFFUSE,
    /** Multiplies ks. */
    SPECULAR,
    /** Multiplies kr. */
    REFLECTION,
    /** Multiplies kt (refraction and shadows through the object), and a principled material's transmission. */
    TRANSPARENCY,
    /** Adds its colour to the material's emission: the light leaving the surface. */
    EMISSION,
    /** A height field, scaled by the material's bump strength, that tilts the shading normal. */
    BUMP,
    /** Multiplies a principled material's roughness, the product clamped to [0, 1]. */
    ROUGHNESS,
    /** Multiplies a principled material's metallic, the product clamped to [0, 1]. */
    METALLIC;

    /**
     * The scene-language word: the lower-case name.
     *
     * @return the keyword
     */
    public String keyword() { return name().toLowerCase(java.util.Locale.ROOT); }

    /**
     * The channel with this scene-language word.
     *
     * @param word the keyword
     * @return the channel
     */
    public static Channel fromKeyword(String word) {
        for (Channel c : values()) if (c.keyword().equals(word)) return c;
        throw new IllegalArgumentException("unknown texture channel '" + word + "'");
    }

    /**
     * Every scene-language word, in declaration order.
     *
     * @return the keywords
     */
    public static java.util.List<String> keywords() {
        java.util.List<String> out = new java.util.ArrayList<>();
        for (Channel c : values()) out.add(c.keyword());
        return java.util.List.copyOf(out);
    }
}
