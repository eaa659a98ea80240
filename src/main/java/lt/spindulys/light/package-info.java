/**
 * Lights as the integrator samples them: one {@link lt.spindulys.light.Light} per point light,
 * area light and lit environment of a frozen scene ({@link lt.spindulys.light.Lights#of}), each
 * drawing its own samples into a per-thread {@link lt.spindulys.light.LightSample} and telling the
 * density of any direction towards it, as pbrt-v4's {@code SampleLi} and {@code PDF_Li} do. The
 * public descriptions ({@code PointLight}, {@code AreaLight}, {@code EnvironmentLight} in
 * {@code scene}) stay what a scene is built from; these classes are per-ray machinery, not
 * exported.
 */
package lt.spindulys.light;
