/**
 * {@code render bench}, the project's benchmark suite: a front end of its own, which the command
 * line dispatches to ({@code render bench ...}) and which never reaches back into it (the main
 * class of the command line, which some rows start in new JVMs to time whole processes, is handed
 * in). Not exported.
 *
 * <p>It measures the library through its exported API, as a library user would: it parses and
 * builds scenes ({@code io}, {@code scene}), renders them ({@code render}), refines control meshes
 * ({@code subdiv}) and reads back images ({@code image}, {@code texture}). Beyond the API it uses:
 * <ul>
 * <li>{@code frontend}, what the front ends share: the program's version for its header and the
 *     peak heap, measured as {@code render --stats} measures it;</li>
 * <li>{@code files}, to write the meshes and peer inputs it generates atomically (an interrupted
 *     bench leaves no half-written mesh for the next run to trust);</li>
 * <li>{@code limits}, to add and print patch sizes in the same words as the library's messages;</li>
 * <li>{@code viewer}, whose software rasterizer the {@code viewer} row times: the viewer is no
 *     part of the library's API.</li>
 * </ul>
 * {@code PackageCyclesTest} holds it to these. The JVM's CPU time of the process
 * ({@code com.sun.management}) is why the module requires {@code jdk.management}.
 */
package lt.spindulys.bench;
