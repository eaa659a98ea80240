/**
 * Output plugins of a subdivision-surface viewer, as in the thesis's chapter 7: a viewer hands
 * what it displays ({@link lt.spindulys.plugin.DisplayedSurface}, {@link lt.spindulys.plugin.PluginView})
 * to an {@link lt.spindulys.plugin.OutputPlugin} found with {@link java.util.ServiceLoader}, which
 * writes a file. The library provides a ray tracer and an OBJ exporter; any viewer written in
 * Java can host them through these types alone.
 */
package lt.spindulys.plugin;
