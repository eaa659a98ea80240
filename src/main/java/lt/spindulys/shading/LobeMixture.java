package lt.spindulys.shading;

/**
 * A weighted sum of BSDF lobes, f = sum_k w_k f_k, sampled as a one-sample mixture: a lobe is
 * chosen with probability proportional to a per-wo estimate of its contribution, then sampled.
 * The machinery shared by {@link PrincipledBsdf} and {@link WhittedMaterialBsdf}.
 *
 * <p>A sample from a non-delta lobe reports f and pdf of the whole mixture (every lobe's f and
 * every non-delta lobe's density, weighted by its selection probability), so multiple importance
 * sampling sees the same density as {@link #pdf}. A delta lobe's sample reports only that lobe:
 * its f times w_k, and its own probability times the selection probability, so f/pdf is the
 * lobe's path weight over its chance of being chosen. Nothing is allocated per call: the estimates
 * are recomputed rather than stored, and eval accumulates in locals while each lobe reuses rgbOut.
 */
final class LobeMixture implements Bsdf {
    /** Contribution estimates used to pick lobes: non-negative, and positive wherever the lobe's f is not zero. */
    interface Estimator {
        /** {@return a cheap estimate of lobe k's contribution for wo} */
        double estimate(int lobe, double wox, double woy, double woz);
    }

    private final Bsdf[] lobes;
    private final double[] weights;
    private final Estimator estimator;
    // Not final only so that a reusable owner can re-parameterise its lobes in place (set, update).
    private boolean specular;
    /** The one lobe of positive weight, or -1 when there are several (or none): most surfaces have one, and skip the mixing. */
    private int single;

    LobeMixture(Bsdf[] lobes, double[] weights, Estimator estimator) {
        this.lobes = lobes.clone();
        this.weights = weights.clone();
        this.estimator = estimator;
        update();
    }

    /** Puts lobe k in place with weight w; {@link #update} must follow once every slot is set. */
    void set(int k, Bsdf lobe, double weight) {
        lobes[k] = lobe;
        weights[k] = weight;
    }

    /** Recomputes what is derived from the lobes and weights, after they or the lobes' own parameters changed. */
    void update() {
        boolean allDelta = true;
        int count = 0, only = -1;
        for (int k = 0; k < lobes.length; k++) {
            if (!(weights[k] > 0)) continue;
            count++;
            only = k;
            if (!lobes[k].isSpecular()) allDelta = false;
        }
        specular = allDelta;
        single = count == 1 ? only : -1;
    }

    @Override
    public boolean isSpecular() { return specular; }

    @Override
    public void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        if (single >= 0) { // one lobe: its value times its weight, as the loop below gives it
            double w = weights[single];
            if (lobes[single].isSpecular()) { rgbOut[0] = rgbOut[1] = rgbOut[2] = 0; return; }
            lobes[single].eval(wox, woy, woz, wix, wiy, wiz, rgbOut);
            rgbOut[0] *= w; rgbOut[1] *= w; rgbOut[2] *= w;
            return;
        }
        double r = 0, g = 0, b = 0;
        for (int k = 0; k < lobes.length; k++) {
            double w = weights[k];
            if (!(w > 0) || lobes[k].isSpecular()) continue;
            lobes[k].eval(wox, woy, woz, wix, wiy, wiz, rgbOut);
            r += w * rgbOut[0]; g += w * rgbOut[1]; b += w * rgbOut[2];
        }
        rgbOut[0] = r; rgbOut[1] = g; rgbOut[2] = b;
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        if (single >= 0) { // one lobe is always the one chosen, where it can be chosen at all
            Bsdf lobe = lobes[single];
            if (lobe.isSpecular() || !(estimator.estimate(single, wox, woy, woz) > 0)) return 0;
            return lobe.pdf(wox, woy, woz, wix, wiy, wiz);
        }
        double total = totalEstimate(wox, woy, woz);
        if (!(total > 0)) return 0;
        double pdf = 0;
        for (int k = 0; k < lobes.length; k++) {
            if (!(weights[k] > 0) || lobes[k].isSpecular()) continue;
            double e = estimator.estimate(k, wox, woy, woz);
            if (e > 0) pdf += e * lobes[k].pdf(wox, woy, woz, wix, wiy, wiz);
        }
        return pdf / total;
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        out.clear();
        if (woz == 0) return false;
        if (single >= 0) return sampleSingle(wox, woy, woz, uc, u1, u2, out);
        double total = totalEstimate(wox, woy, woz);
        if (!(total > 0)) return false;
        double target = uc * total, below = 0;
        int chosen = -1;
        double chosenEstimate = 0;
        for (int k = 0; k < lobes.length; k++) {
            if (!(weights[k] > 0)) continue;
            double e = estimator.estimate(k, wox, woy, woz);
            if (!(e > 0)) continue;
            chosen = k;
            chosenEstimate = e;
            if (target < below + e) break;
            below += e; // rounding may leave target past the last lobe: the last one keeps it
        }
        if (chosen < 0) return false;
        // Reuse what is left of uc inside the chosen interval, so a lobe that picks a sub-lobe (glass: R or T) still gets a uniform.
        double ucLobe = Math.min(Math.max((target - below) / chosenEstimate, 0), Math.nextDown(1.0));
        Bsdf lobe = lobes[chosen];
        if (!lobe.sample(wox, woy, woz, ucLobe, u1, u2, out)) { out.clear(); return false; }
        double probability = chosenEstimate / total;
        if (out.specular) {
            double w = weights[chosen];
            out.f[0] *= w; out.f[1] *= w; out.f[2] *= w;
            out.pdf *= probability;
            return true;
        }
        double wix = out.wix, wiy = out.wiy, wiz = out.wiz, eta = out.eta;
        double pdf = pdf(wox, woy, woz, wix, wiy, wiz);
        if (!(pdf > 0) || Double.isInfinite(pdf)) { out.clear(); return false; }
        eval(wox, woy, woz, wix, wiy, wiz, out.f);
        out.pdf = pdf;
        out.eta = eta;
        return true;
    }

    /** {@link #sample} of a mixture of one lobe: that lobe's sample, its value weighted. */
    private boolean sampleSingle(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        if (!(estimator.estimate(single, wox, woy, woz) > 0)) return false;
        if (!lobes[single].sample(wox, woy, woz, uc, u1, u2, out)) { out.clear(); return false; }
        if (!(out.pdf > 0) || Double.isInfinite(out.pdf)) { out.clear(); return false; }
        double w = weights[single];
        out.f[0] *= w; out.f[1] *= w; out.f[2] *= w;
        return true;
    }

    private double totalEstimate(double wox, double woy, double woz) {
        double total = 0;
        for (int k = 0; k < lobes.length; k++) {
            if (!(weights[k] > 0)) continue;
            double e = estimator.estimate(k, wox, woy, woz);
            if (e > 0) total += e;
        }
        return total;
    }
}
