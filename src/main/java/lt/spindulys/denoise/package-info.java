/**
 * Denoising of Monte Carlo renders guided by what the camera rays saw first: the
 * {@link lt.spindulys.denoise.FeatureFrame} a render gathers beside its colour (albedo, normal,
 * inverse depth, the variance of each pixel's mean) and the {@link lt.spindulys.denoise.Denoiser}
 * that filters the colour with them, by a first-order regression on the (prefiltered) features
 * weighted by non-local means (after Bitterli et al., "Nonlinearly Weighted First-order
 * Regression for Denoising Monte Carlo Renderings", EGSR 2016, simplified).
 */
package lt.spindulys.denoise;
