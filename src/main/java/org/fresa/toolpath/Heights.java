package org.fresa.toolpath;

/**
 * The heights of one feature along its tool axis, in the feature frame (mm): the tool comes from
 * and returns to the clearance height (the security plane), moves between cuts at the retract
 * height, and removes material from top down to bottom.
 */
public record Heights(double clearanceZ, double retractZ, double topZ, double bottomZ) {

    public Heights {
        if (!(clearanceZ >= retractZ && retractZ >= topZ && topZ >= bottomZ)) {
            throw new IllegalArgumentException("heights must satisfy clearance >= retract >= top >= bottom: "
                    + clearanceZ + ", " + retractZ + ", " + topZ + ", " + bottomZ);
        }
    }

    /**
     * The layer heights from the first below the top down to the bottom, spaced by the axial
     * depth (the last layer takes the remainder); one layer when the axial depth is not positive.
     */
    public double[] layers(double axialDepthMm) {
        double depth = topZ - bottomZ;
        if (!(axialDepthMm > 0) || depth <= axialDepthMm) {
            return new double[] {bottomZ};
        }
        int n = (int) Math.ceil(depth / axialDepthMm - 1e-9);
        double[] z = new double[n];
        for (int i = 0; i < n; i++) {
            z[i] = i == n - 1 ? bottomZ : topZ - axialDepthMm * (i + 1);
        }
        return z;
    }
}
