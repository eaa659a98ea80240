package lt.spindulys.shading;

import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Mapping;
import lt.spindulys.texture.Texture;
import lt.spindulys.texture.TexturePoint;

/**
 * Evaluates a material's texture channels at a hit, without allocating (all scratch is the
 * thread's {@link TracerScratch}).
 *
 * <p>Footprint: the caller gives the width w of the pixel's footprint on the surface in world
 * units (distance travelled along the ray path times the camera's pixel angle, divided by the
 * cosine of the incidence angle, which is limited to 1/4). It is turned into object units with the
 * ratio |dp/du| object / |dp/du| world (exact for rotations and uniform scales) and handed to the
 * mapping, which converts it to (u, v) units. Curvature of reflecting and refracting surfaces is
 * ignored: a reflected texture is filtered as if seen directly at the same path length.
 */
final class TextureShading {
    private TextureShading() {}

    /** Height differences for bump mapping use a step no smaller than this (object units). */
    private static final double MIN_BUMP_STEP = 1e-4;

    /**
     * Fills v's surface terms with those after the material's textures (colour, ks, kr, kt,
     * metallic, roughness, transmission, emission) and, if a bump texture is bound, tilts sd.ns.
     *
     * @param worldFootprint footprint width in world units (0: sharpest)
     */
    static void evaluate(Material m, ShadingData sd, double worldFootprint, TracerScratch s, TracerScratch.PathVertex v) {
        v.colourR = m.color().r(); v.colourG = m.color().g(); v.colourB = m.color().b();
        v.ks = m.ks(); v.kr = m.kr(); v.kt = m.kt();
        v.metallic = m.metallic(); v.roughness = m.roughness(); v.transmission = m.transmission();
        Color e = m.emission();
        v.emissionR = e.r(); v.emissionG = e.g(); v.emissionB = e.b();
        if (!m.isTextured()) return;
        double objectFootprint = worldFootprint * objectPerWorld(sd);
        double[] rgb = s.texRgb;
        if (sample(m, Channel.DIFFUSE, sd, sd.pObject, objectFootprint, s, rgb)) {
            v.colourR *= rgb[0]; v.colourG *= rgb[1]; v.colourB *= rgb[2];
            // A base colour is a reflectance: above 1 the principled BSDF would make light.
            if (m.model() == Material.Model.PRINCIPLED) {
                v.colourR = fraction(v.colourR); v.colourG = fraction(v.colourG); v.colourB = fraction(v.colourB);
            }
        }
        if (sample(m, Channel.SPECULAR, sd, sd.pObject, objectFootprint, s, rgb)) v.ks *= mean(rgb);
        // kr and kt textures are fractions: clamped to [0, 1], so a path never gains (see Ranges).
        if (sample(m, Channel.REFLECTION, sd, sd.pObject, objectFootprint, s, rgb)) v.kr *= fraction(mean(rgb));
        if (sample(m, Channel.TRANSPARENCY, sd, sd.pObject, objectFootprint, s, rgb)) {
            double f = fraction(mean(rgb));
            v.kt *= f;
            v.transmission *= f;
        }
        // Added to the material's own emission, black unless given: 0 + x is x, so a texture
        // alone gives exactly its colour.
        if (sample(m, Channel.EMISSION, sd, sd.pObject, objectFootprint, s, rgb)) {
            v.emissionR += rgb[0]; v.emissionG += rgb[1]; v.emissionB += rgb[2];
        }
        // No energy is at stake, so the product is clamped (a texture may raise the value), not the factor.
        if (sample(m, Channel.ROUGHNESS, sd, sd.pObject, objectFootprint, s, rgb)) v.roughness = fraction(v.roughness * mean(rgb));
        if (sample(m, Channel.METALLIC, sd, sd.pObject, objectFootprint, s, rgb)) v.metallic = fraction(v.metallic * mean(rgb));
        if (m.texture(Channel.BUMP) != null) bump(m, sd, objectFootprint, s);
    }

    /** kt at a hit a shadow ray crosses, after a transparency texture (sharpest filtering). */
    static double shadowKt(Material m, ShadingData sd, TracerScratch s) {
        double kt = m.kt();
        if (sample(m, Channel.TRANSPARENCY, sd, sd.pObject, 0, s, s.texRgb)) kt *= fraction(mean(s.texRgb));
        return kt;
    }

    private static double mean(double[] rgb) { return (rgb[0] + rgb[1] + rgb[2]) / 3; }

    /** {@code v} clamped to [0, 1]. */
    private static double fraction(double v) { return v > 0 ? (v < 1 ? v : 1) : 0; }

    /** Evaluates the channel's texture at object point p into rgb; false if the channel has none. */
    private static boolean sample(Material m, Channel c, ShadingData sd, double[] p, double objectFootprint, TracerScratch s, double[] rgb) {
        Texture tex = m.texture(c);
        if (tex == null) return false;
        TexturePoint tp = s.texPoint;
        tp.footprint = objectFootprint;
        m.mapping(c).map(sd.u, sd.v, sd.dpduObject, sd.dpdvObject, p, tp);
        tex.evaluate(tp, rgb);
        return true;
    }

    /** Object units per world unit along the surface at the hit (1 where the surface has no derivatives). */
    private static double objectPerWorld(ShadingData sd) {
        double w = length(sd.dpdu), o = length(sd.dpduObject);
        if (!(w > 0) || !(o > 0)) {
            w = length(sd.dpdv);
            o = length(sd.dpdvObject);
        }
        return w > 0 && o > 0 ? o / w : 1;
    }

    private static double length(double[] v) { return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

    /**
     * Tilts the shading normal as if the surface were displaced along it by strength * height:
     * with height derivatives hu, hv (forward differences of the texture over a step of about
     * the footprint along dp/du and dp/dv), the displaced surface's normal is
     * dp/du x dp/dv + hu (n x dp/dv) + hv (dp/du x n), oriented like n. Where the surface has no
     * derivatives (a degenerate parametrisation point) the normal is left as it is.
     */
    private static void bump(Material m, ShadingData sd, double objectFootprint, TracerScratch s) {
        double lu = length(sd.dpduObject), lv = length(sd.dpdvObject);
        if (!(lu > 0) || !(lv > 0)) return;
        Texture tex = m.texture(Channel.BUMP);
        Mapping map = m.mapping(Channel.BUMP);
        TexturePoint tp = s.texPoint;
        double[] sc = s.texScratch, q = s.texObject, po = sd.pObject;
        double step = Math.max(objectFootprint, MIN_BUMP_STEP * (1 + Math.max(Math.abs(po[0]), Math.max(Math.abs(po[1]), Math.abs(po[2])))));
        double du = step / lu, dv = step / lv;

        tp.footprint = objectFootprint;
        map.map(sd.u, sd.v, sd.dpduObject, sd.dpdvObject, po, tp);
        double h0 = tex.scalar(tp, sc);

        double u0 = sd.u, v0 = sd.v;
        for (int i = 0; i < 3; i++) q[i] = po[i] + sd.dpduObject[i] * du;
        sd.u = u0 + du;
        tp.footprint = objectFootprint;
        map.map(sd.u, sd.v, sd.dpduObject, sd.dpdvObject, q, tp);
        double h1 = tex.scalar(tp, sc);
        sd.u = u0;

        for (int i = 0; i < 3; i++) q[i] = po[i] + sd.dpdvObject[i] * dv;
        sd.v = v0 + dv;
        tp.footprint = objectFootprint;
        map.map(sd.u, sd.v, sd.dpduObject, sd.dpdvObject, q, tp);
        double h2 = tex.scalar(tp, sc);
        sd.v = v0;

        // Heights are object units; the world derivatives need world units.
        double k = m.bumpStrength() / objectPerWorld(sd);
        double hu = k * (h1 - h0) / du, hv = k * (h2 - h0) / dv;
        double[] a = sd.dpdu, b = sd.dpdv, n = sd.ns;
        double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
        double sign = cx * n[0] + cy * n[1] + cz * n[2] < 0 ? -1 : 1;
        // n x dpdv and dpdu x n
        double ax = n[1] * b[2] - n[2] * b[1], ay = n[2] * b[0] - n[0] * b[2], az = n[0] * b[1] - n[1] * b[0];
        double bx = a[1] * n[2] - a[2] * n[1], by = a[2] * n[0] - a[0] * n[2], bz = a[0] * n[1] - a[1] * n[0];
        // The unperturbed part is taken along n (its length |dpdu x dpdv|) so smooth shading survives.
        double len0 = Math.sqrt(cx * cx + cy * cy + cz * cz);
        double nx = len0 * n[0] + sign * (hu * ax + hv * bx);
        double ny = len0 * n[1] + sign * (hu * ay + hv * by);
        double nz = len0 * n[2] + sign * (hu * az + hv * bz);
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 0) || !Double.isFinite(len)) return;
        n[0] = nx / len; n[1] = ny / len; n[2] = nz / len;
    }
}
