package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.fresa.cell.RobotFiles;
import picocli.CommandLine.Command;

/** {@code fresa robots}: the built-in robots and their parameters. */
@Command(name = "robots", description = "List the built-in robots and their parameters.")
final class RobotsCommand extends ListingCommand {

    @Override
    Map<String, Object> listing() {
        return RobotFiles.describeBuiltIns();
    }

    @Override
    void print(Map<String, Object> all, PrintWriter out) {
        for (Object o : (List<?>) all.get("robots")) {
            Map<?, ?> r = (Map<?, ?>) o;
            out.println(r.get("name") + ": " + r.get("description"));
            for (Object jo : (List<?>) r.get("joints")) {
                Map<?, ?> j = (Map<?, ?>) jo;
                StringBuilder sb = new StringBuilder(String.format(
                        Locale.ROOT,
                        "  %-3s %-9s %9s .. %-9s %s",
                        j.get("name"),
                        j.get("type"),
                        num(j.get("min")),
                        num(j.get("max")),
                        j.get("unit")));
                if (j.containsKey("a_mm")) {
                    sb.append(String.format(
                            Locale.ROOT,
                            "   a %s  alpha %s  d %s  theta %s",
                            num(j.get("a_mm")),
                            num(j.get("alpha_deg")),
                            j.containsKey("d_mm") ? num(j.get("d_mm")) : variable(j.get("d_offset_mm")),
                            j.containsKey("theta_offset_deg")
                                    ? variable(j.get("theta_offset_deg"))
                                    : num(j.get("theta_deg"))));
                }
                out.println(sb);
            }
            if (r.containsKey("base_radius_mm")) {
                out.println("  r_b " + num(r.get("base_radius_mm")) + " mm, r_p " + num(r.get("platform_radius_mm"))
                        + " mm, d_eff " + num(r.get("centre_offset_mm")) + " mm, e_ffl "
                        + num(r.get("effector_length_mm")) + " mm");
            }
        }
    }

    private static String variable(Object offset) {
        double c = ((Number) offset).doubleValue();
        return c == 0 ? "q" : (c > 0 ? "q + " : "q - ") + num(Math.abs(c));
    }

    private static String num(Object o) {
        return org.fresa.model.ExactDecimal.of(((Number) o).doubleValue());
    }
}
