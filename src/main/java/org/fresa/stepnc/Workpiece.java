package org.fresa.stepnc;

import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Transform3;

/**
 * WORKPIECE with its bounding block when the file gives one.
 *
 * @param material material_identifier, when given
 * @param globalTolerance as written (mm in ISO 14649-10)
 * @param block its_bounding_geometry when it is a BLOCK (in the AIM a BLOCK_SHAPE_REPRESENTATION,
 *     read from its corner as the BLOCK)
 */
public record Workpiece(
        long instanceId, String id, Optional<String> material, OptionalDouble globalTolerance, Optional<Block> block) {
    public Workpiece {
        Objects.requireNonNull(id);
        Objects.requireNonNull(material);
        Objects.requireNonNull(globalTolerance);
        Objects.requireNonNull(block);
    }

    /**
     * BLOCK (ISO 10303-42 CSG): a box from the corner at the placement's origin along its +x, +y
     * and +z axes.
     *
     * @param placement the block frame in the workpiece frame
     */
    public record Block(Transform3 placement, double xMm, double yMm, double zMm) {
        public Block {
            Objects.requireNonNull(placement);
        }
    }
}
