package lt.spindulys.shading;

/**
 * A BSDF that is a weighted sum of lobes ({@link LobeMixture}): the materials that are built
 * from several lobes hand every query to their mixture, and differ only in how they make it.
 */
abstract class MixtureBsdf implements Bsdf {
    /**
     * The lobes and their weights, set by the subclass: once in its constructor (not passed up:
     * its lobe estimates are the subclass's own methods, which cannot be named before super()),
     * or per hit by {@link SurfaceBsdf}.
     */
    LobeMixture mixture;

    @Override
    public void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        mixture.eval(wox, woy, woz, wix, wiy, wiz, rgbOut);
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        return mixture.pdf(wox, woy, woz, wix, wiy, wiz);
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        return mixture.sample(wox, woy, woz, uc, u1, u2, out);
    }

    @Override
    public boolean isSpecular() { return mixture.isSpecular(); }
}
