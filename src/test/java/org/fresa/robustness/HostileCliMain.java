package org.fresa.robustness;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.app.cli.FresaCommand;

/**
 * Runs command lines in this JVM, one per line of a plan file ({@code name<TAB>arg<TAB>arg...}),
 * and prints {@code name<TAB>status<TAB>millis<TAB>stderr} per line (tabs and newlines in stderr
 * as spaces). {@link HostileCliTest} starts it in a JVM with a small heap and stack, so that an
 * unbounded allocation or recursion shows as an error instead of passing on a 2 GB test heap.
 */
public final class HostileCliMain {

    private HostileCliMain() {}

    public static void main(String[] args) throws Exception {
        List<String> lines = Files.readAllLines(Path.of(args[0]));
        PrintWriter out = new PrintWriter(System.out, true);
        for (String line : lines) {
            String[] f = line.split("\t");
            List<String> cli = new ArrayList<>(List.of(f).subList(1, f.length));
            StringWriter so = new StringWriter();
            StringWriter se = new StringWriter();
            long t0 = System.nanoTime();
            int status = FresaCommand.execute(
                    new PrintWriter(so, true), new PrintWriter(se, true), cli.toArray(String[]::new));
            long ms = (System.nanoTime() - t0) / 1_000_000;
            out.println(f[0] + "\t" + status + "\t" + ms + "\t" + se.toString().replaceAll("[\t\r\n]+", " ") + " | "
                    + so.toString().replaceAll("[\t\r\n]+", " "));
        }
        out.println("END");
    }
}
