package org.fresa.kin;

import java.util.LinkedHashMap;
import java.util.Map;
import org.fresa.geom.Transform3;

/**
 * The error of reached poses against their targets per axis, as the 2016 thesis's Table 5.3 gives
 * it (mean, lower and upper error per axis): position target - reached along x, y, z of the robot
 * base frame (mm), orientation as the rotation vector of R_target R_reached^T, whose components
 * about x, y, z (rad) are the small turns that would take the reached tool onto the target.
 * Not thread-safe.
 */
public final class ErrorStatistics {

    /**
     * One axis: the mean, least and largest target - reached.
     *
     * @param name as in summary.json: x_mm, y_mm, z_mm, rx_rad, ry_rad, rz_rad
     */
    public record Axis(String name, double mean, double min, double max) {
        /** The axis without its unit: x, y, z, rx, ry, rz. */
        public String axis() {
            return name.substring(0, name.indexOf('_'));
        }

        /** mm or rad. */
        public String unit() {
            return name.substring(name.indexOf('_') + 1);
        }
    }

    /** The statistics of every point of a trajectory that reached its target. */
    public static ErrorStatistics of(TrajectorySolver.Result r) {
        ErrorStatistics s = new ErrorStatistics();
        for (org.fresa.kin.TrajectoryPoint p : r.points()) {
            if (p.status() != org.fresa.kin.TrajectoryPoint.Status.UNREACHABLE
                    && p.reached().isPresent()) {
                s.add(p.target(), p.reached().get());
            }
        }
        return s;
    }

    /** The six axes (x, y, z in mm, then rx, ry, rz in rad); empty when no pose was added. */
    public java.util.List<Axis> axes() {
        java.util.List<Axis> out = new java.util.ArrayList<>();
        for (int i = 0; i < 6 && count > 0; i++) {
            out.add(new Axis(NAMES[i], sum[i] / count, min[i], max[i]));
        }
        return out;
    }

    /**
     * The legend of a position error curve (x, y or z: index 0..2) with its figures in um, as
     * error.png and the Position tab's plot show them.
     */
    public String positionLegend(int axis) {
        String[] n = {"x", "y", "z"};
        if (count == 0) {
            return "error " + n[axis];
        }
        return String.format(
                java.util.Locale.ROOT,
                "error %s: mean %.3g, min %.3g, max %.3g um",
                n[axis],
                sum[axis] / count * 1000,
                min[axis] * 1000,
                max[axis] * 1000);
    }

    /** One line on the orientation errors about x, y, z (urad), for under error.png's title. */
    public String orientationLine() {
        if (count == 0) {
            return "";
        }
        StringBuilder sb = new StringBuilder("orientation error (urad):");
        String[] n = {"rx", "ry", "rz"};
        for (int i = 3; i < 6; i++) {
            sb.append(String.format(
                    java.util.Locale.ROOT,
                    " %s mean %.3g, min %.3g, max %.3g%s",
                    n[i - 3],
                    sum[i] / count * 1e6,
                    min[i] * 1e6,
                    max[i] * 1e6,
                    i < 5 ? ";" : ""));
        }
        return sb.toString();
    }

    private static final String[] NAMES = {"x_mm", "y_mm", "z_mm", "rx_rad", "ry_rad", "rz_rad"};

    private final double[] sum = new double[6];
    private final double[] min = new double[6];
    private final double[] max = new double[6];
    private int count;
    private double maxPosMm;
    private double maxRotRad;

    public ErrorStatistics() {
        java.util.Arrays.fill(min, Double.POSITIVE_INFINITY);
        java.util.Arrays.fill(max, Double.NEGATIVE_INFINITY);
    }

    /** Adds one reached pose. */
    public void add(Transform3 target, Transform3 reached) {
        double[] e = new double[6];
        e[0] = target.tx() - reached.tx();
        e[1] = target.ty() - reached.ty();
        e[2] = target.tz() - reached.tz();
        // E = R_t R_r^T; its skew part is sin(angle) * axis
        Transform3 big = target.times(reached.inverse());
        double sx = (big.r21() - big.r12()) / 2;
        double sy = (big.r02() - big.r20()) / 2;
        double sz = (big.r10() - big.r01()) / 2;
        double s = Math.sqrt(sx * sx + sy * sy + sz * sz);
        double angle = Math.atan2(s, (big.r00() + big.r11() + big.r22() - 1) / 2);
        double k = s > 1e-300 ? angle / s : 1;
        e[3] = sx * k;
        e[4] = sy * k;
        e[5] = sz * k;
        maxPosMm = Math.max(maxPosMm, Math.sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]));
        maxRotRad = Math.max(maxRotRad, Math.abs(angle));
        for (int i = 0; i < 6; i++) {
            sum[i] += e[i];
            min[i] = Math.min(min[i], e[i]);
            max[i] = Math.max(max[i], e[i]);
        }
        count++;
    }

    /** The largest |target - reached| (mm). */
    public double maxPosMm() {
        return maxPosMm;
    }

    /** The largest orientation error angle (rad). */
    public double maxRotRad() {
        return maxRotRad;
    }

    /**
     * {@code error_per_axis}: for each of x_mm, y_mm, z_mm, rx_rad, ry_rad, rz_rad its mean, min
     * and max over the poses added (absent when there are none).
     */
    public Map<String, Object> summary() {
        Map<String, Object> axes = new LinkedHashMap<>();
        if (count > 0) {
            for (int i = 0; i < 6; i++) {
                Map<String, Object> a = new LinkedHashMap<>();
                a.put("mean", sum[i] / count);
                a.put("min", min[i]);
                a.put("max", max[i]);
                axes.put(NAMES[i], a);
            }
        }
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("error_per_axis", axes);
        return m;
    }
}
