/**
 * The ray-tracing output plugin ({@link lt.spindulys.plugin.raytrace.RayTracePlugin}, id
 * {@code raytrace}): the thesis's chapter 7 plugin, which turns what a viewer shows into a scene
 * through the public builder API, renders it and writes the picture, and can save the same scene
 * as a .dat file and a picture identifying each surface. Found with
 * {@link java.util.ServiceLoader}; hosts use it through {@link lt.spindulys.plugin} alone, so this
 * package is not exported. See docs/plugins.md.
 */
package lt.spindulys.plugin.raytrace;
