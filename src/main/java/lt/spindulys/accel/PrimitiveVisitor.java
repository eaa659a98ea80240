package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/** Called for each primitive of {@link Accelerator#visit}, which a structure cannot rule out for the ray. */
@FunctionalInterface
public interface PrimitiveVisitor {
    void visit(int prim, Ray ray, TraversalScratch ctx);
}
