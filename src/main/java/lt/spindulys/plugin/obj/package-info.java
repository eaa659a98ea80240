/**
 * The OBJ-export output plugin ({@link lt.spindulys.plugin.obj.ObjExportPlugin}): the displayed
 * surfaces as Wavefront OBJ, control meshes with their OpenSubdiv tags or refined at the host's
 * levels. Provided through the module descriptor and {@code META-INF/services}; not exported, since
 * hosts reach it through {@link lt.spindulys.plugin.OutputPlugin} alone.
 */
package lt.spindulys.plugin.obj;
