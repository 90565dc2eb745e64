package org.fresa.robustness;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.fresa.app.cli.FresaCommand;

/**
 * Runs the command lines of a plan file ({@code name<TAB>arg<TAB>arg...}) from a given line on,
 * each in this JVM with a deadline, and prints {@code name<TAB>status<TAB>millis<TAB>cpu
 * millis<TAB>stderr} per line: the wall time, and the CPU time the JVM spent meanwhile (one
 * command runs at a time, so that is the command's cost, whatever else loads the machine). A
 * command past its deadline is printed with status {@code TIMEOUT} and the JVM halts
 * at once (the command's thread cannot be stopped); {@link HostileOptionsTest} then starts a new
 * JVM on the next line.
 */
public final class HostileOptionsMain {

    private static final com.sun.management.OperatingSystemMXBean CPU = (com.sun.management.OperatingSystemMXBean)
            java.lang.management.ManagementFactory.getOperatingSystemMXBean();

    private HostileOptionsMain() {}

    public static void main(String[] args) throws Exception {
        List<String> lines = Files.readAllLines(Path.of(args[0]));
        int from = Integer.parseInt(args[1]);
        long deadlineMs = Long.parseLong(args[2]);
        PrintWriter out = new PrintWriter(System.out, true);
        ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "hostile-option");
            t.setDaemon(true);
            return t;
        });
        for (int i = from; i < lines.size(); i++) {
            String[] f = lines.get(i).split("\t");
            String[] cli = List.of(f).subList(1, f.length).toArray(String[]::new);
            StringWriter se = new StringWriter();
            long t0 = System.nanoTime();
            long cpu0 = CPU.getProcessCpuTime();
            Future<Integer> run = worker.submit(() ->
                    FresaCommand.execute(new PrintWriter(new StringWriter(), true), new PrintWriter(se, true), cli));
            String status;
            try {
                status = Integer.toString(run.get(deadlineMs, TimeUnit.MILLISECONDS));
            } catch (TimeoutException e) {
                status = "TIMEOUT";
            } catch (ExecutionException e) {
                // an Error the command let through (OutOfMemoryError, StackOverflowError)
                status = "ERROR";
                se.write(" " + e.getCause());
            }
            long ms = (System.nanoTime() - t0) / 1_000_000;
            long cpuMs = (CPU.getProcessCpuTime() - cpu0) / 1_000_000;
            out.println(f[0] + "\t" + status + "\t" + ms + "\t" + cpuMs + "\t"
                    + se.toString().replaceAll("[\t\r\n]+", " "));
            if (status.equals("TIMEOUT")) {
                out.flush();
                Runtime.getRuntime().halt(3);
            }
        }
        out.println("END");
        out.flush();
        worker.shutdownNow();
    }
}
