package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.fresa.cell.RobotFiles;
import org.fresa.io.Json;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fresa robots}: the built-in robots and their parameters. */
@Command(
        name = "robots",
        mixinStandardHelpOptions = true,
        description = "List the built-in robots and their parameters.")
final class RobotsCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--json", description = "print as JSON")
    boolean json;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        Map<String, Object> all = RobotFiles.describeBuiltIns();
        if (json) {
            out.println(Json.write(all));
            out.flush();
            return CliSupport.EXIT_OK;
        }
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
        out.flush();
        return CliSupport.EXIT_OK;
    }

    private static String variable(Object offset) {
        double c = ((Number) offset).doubleValue();
        return c == 0 ? "q" : (c > 0 ? "q + " : "q - ") + num(Math.abs(c));
    }

    private static String num(Object o) {
        return org.fresa.model.ExactDecimal.of(((Number) o).doubleValue());
    }
}
