package org.fresa.bench;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fresa.cutting.Chainer;
import org.fresa.dxf.DxfDrawing;
import org.fresa.dxf.DxfReadOptions;
import org.fresa.dxf.DxfReader;
import org.fresa.job.CuttingService;
import org.fresa.job.JobSettings;
import org.fresa.job.PocketService;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.kin.IkBenchmark;
import org.fresa.model.CamInputException;
import org.fresa.pocket.PocketTechnology;
import org.fresa.post.PocketPost;
import org.fresa.stepnc.StepNcReader;

/**
 * The short benchmarks of {@code fresa bench}: each figure is the median of repeated
 * runs after a JIT warm-up, measured in this JVM (except the whole-process figure, which starts a
 * fresh one). The inputs are resources of the jar ({@value #INPUTS}: example part 2, cavity 02 and
 * the 10 052-line ezdxf drawing), so that a copied jar or an installed app image measures the
 * same files as a checkout. A figure that cannot be measured is null, with the reason.
 */
public final class Benchmarks {

    /** The performance goals (docs/performance.md): figure name to goal (a maximum, or a minimum for *_per_s). */
    public static final Map<String, Double> GOALS = Map.of(
            "ik_us_per_point_irb140", 5.0,
            "ik_us_per_point_tricept806", 10.0,
            "ik_cold_cpu_us_per_pose_irb140", 10.0,
            "part21_mb_per_s", 20.0,
            "dxf_mb_per_s", 30.0,
            "pocket_ms_cavity02", 50.0,
            "cut_parts_per_s", (double) SquareSheet.FIFTY_MB_SQUARES / 60,
            "example2_irb140_process_s", 3.0);

    /** Where the inputs are in the jar (pom.xml's resources). */
    static final String INPUTS = "/org/fresa/bench/";

    static final String EXAMPLE2 = "stepnc/example2.stp";
    static final String CAVITY02 = "pocket/cavity02.dad";
    static final String DXF = "ezdxf/examples_edgeminer_3_us_main.dxf";

    private Benchmarks() {}

    /** The bytes of one benchmark input. */
    static byte[] input(String name) throws IOException {
        try (java.io.InputStream in = Benchmarks.class.getResourceAsStream(INPUTS + name)) {
            if (in == null) {
                throw new java.io.FileNotFoundException("benchmark input " + INPUTS + name + " is not in the jar");
            }
            return in.readAllBytes();
        }
    }

    /** One benchmark input as a temporary file, for the code that reads files; the caller deletes it. */
    static Path inputFile(String name) throws IOException {
        String file = name.substring(name.lastIndexOf('/') + 1);
        Path f = Files.createTempFile("fresa-bench-", "-" + file);
        Files.write(f, input(name));
        return f;
    }

    /**
     * How long the figures are measured: the bench's warm-ups and sheet, or a short pass that
     * only shows every figure comes out (a test's, a few seconds of CPU; its figures mean little).
     */
    record Effort(long warmUpMinNs, long warmUpMaxNs, int cutSquares) {
        static final Effort FULL = new Effort(WARM_UP_MIN_NS, WARM_UP_MAX_NS, CUT_SQUARES);
        static final Effort QUICK = new Effort(200_000_000L, 400_000_000L, 200);
    }

    /**
     * Runs every figure.
     *
     * @param jar the Fresa jar for the whole-process figure, or null to skip it
     */
    public static Map<String, Object> run(Path jar, ProgressMonitor progress) {
        return run(jar, progress, Effort.FULL);
    }

    static Map<String, Object> run(Path jar, ProgressMonitor progress, Effort effort) {
        Map<String, Object> figures = new LinkedHashMap<>();
        Map<String, Object> notes = new LinkedHashMap<>();
        progress.progress(0.0, "inverse kinematics, IRB-140");
        IkBenchmark.Figure irb = IkBenchmark.irb140(9);
        figures.put("ik_us_per_point_irb140", irb.usPerPoint());
        figures.put("ik_cpu_us_per_point_irb140", irb.cpuUsPerPoint());
        progress.progress(0.15, "inverse kinematics, Tricept 806");
        figures.put("ik_cold_cpu_us_per_pose_irb140", IkBenchmark.irb140ColdCpuUsPerPose(9));
        IkBenchmark.Figure tri = IkBenchmark.tricept806(9);
        figures.put("ik_us_per_point_tricept806", tri.usPerPoint());
        figures.put("ik_cpu_us_per_point_tricept806", tri.cpuUsPerPoint());
        progress.progress(0.3, "Part 21");
        try {
            Rate r = part21MbPerS(input(EXAMPLE2), effort);
            figures.put("part21_mb_per_s", r.wall());
            figures.put("part21_cpu_mb_per_s", r.cpu());
        } catch (IOException | CamInputException e) {
            figures.put("part21_mb_per_s", null);
            notes.put("part21_mb_per_s", e.getMessage());
        }
        progress.progress(0.45, "DXF");
        try {
            Rate r = dxfMbPerS(input(DXF), effort);
            figures.put("dxf_mb_per_s", r.wall());
            figures.put("dxf_cpu_mb_per_s", r.cpu());
        } catch (IOException | CamInputException e) {
            figures.put("dxf_mb_per_s", null);
            notes.put("dxf_mb_per_s", e.getMessage());
        }
        progress.progress(0.6, "pocket cavity02");
        try {
            figures.put("pocket_ms_cavity02", pocketMs());
        } catch (IOException | CamInputException | RuntimeException e) {
            figures.put("pocket_ms_cavity02", null);
            notes.put("pocket_ms_cavity02", e.getMessage());
        }
        progress.progress(0.7, "cutting a sheet of " + effort.cutSquares() + " square parts");
        try {
            Rate r = cutPartsPerS(effort.cutSquares());
            figures.put("cut_parts_per_s", r.wall());
            figures.put("cut_cpu_parts_per_s", r.cpu());
        } catch (IOException | CamInputException | RuntimeException e) {
            figures.put("cut_parts_per_s", null);
            notes.put("cut_parts_per_s", e.getMessage());
        }
        progress.progress(0.75, "example 2 on the IRB-140, a fresh JVM");
        if (jar != null) {
            try {
                figures.put("example2_irb140_process_s", processSeconds(jar));
                notes.put("example2_irb140_process_s", processNote(jar));
            } catch (IOException e) {
                figures.put("example2_irb140_process_s", null);
                notes.put("example2_irb140_process_s", e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                figures.put("example2_irb140_process_s", null);
            }
        } else {
            figures.put("example2_irb140_process_s", null);
            notes.put("example2_irb140_process_s", "not run from the jar");
        }
        progress.progress(1, "done");
        Map<String, Object> out = new LinkedHashMap<>(figures);
        out.put("cores", Runtime.getRuntime().availableProcessors());
        Map<String, Object> met = new LinkedHashMap<>();
        GOALS.forEach((k, goal) -> {
            Object v = figures.get(k);
            met.put(k, v instanceof Double d ? (k.endsWith("_per_s") ? d >= goal : d <= goal) : null);
        });
        out.put("goals", new LinkedHashMap<>(GOALS));
        out.put("met", met);
        if (!notes.isEmpty()) {
            out.put("notes", notes);
        }
        return out;
    }

    static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }

    /**
     * A throughput, MB (10^6 bytes) per second: of wall-clock time, and of this thread's CPU time
     * (which a loaded machine disturbs less).
     */
    record Rate(double wall, double cpu) {}

    private static final long WARM_UP_NS = 2_000_000_000L;

    private static final java.lang.management.ThreadMXBean THREADS =
            java.lang.management.ManagementFactory.getThreadMXBean();

    /** One read (and whatever goes with it) of a benchmark, returning the bytes it read. */
    @FunctionalInterface
    interface Run {
        long once() throws IOException, CamInputException;
    }

    /** Warm-up windows of 200 ms, for at least {@link #WARM_UP_MIN_NS} and at most {@link #WARM_UP_MAX_NS}. */
    private static final long WINDOW_NS = 200_000_000L;

    private static final long WARM_UP_MIN_NS = 5_000_000_000L;
    private static final long WARM_UP_MAX_NS = 12_000_000_000L;

    /**
     * Runs until the JIT has done its work: windows of 200 ms for at least 5 s and then until the
     * median rate (thread CPU) of the last five windows is no more than 5 % above that of the
     * five before, or 12 s have passed. A fixed 2 s was not enough for the Part 21 reader: on a
     * machine at load 4 its rate still rose from 20 to 45 MB/s between 2 and 4.5 s, so the figure
     * measured the JIT's progress instead of the code; a rule on single windows stopped early on
     * one lucky window.
     *
     * @return how long the warm-up took, in ns
     */
    static long warmUp(Run run) throws IOException, CamInputException {
        return warmUp(run, Effort.FULL);
    }

    static long warmUp(Run run, Effort effort) throws IOException, CamInputException {
        long w0 = System.nanoTime();
        List<Double> rates = new ArrayList<>();
        while (System.nanoTime() - w0 < effort.warmUpMaxNs()) {
            long t0 = System.nanoTime();
            long c0 = THREADS.getCurrentThreadCpuTime();
            long bytes = 0;
            while (System.nanoTime() - t0 < WINDOW_NS) {
                bytes += run.once();
            }
            rates.add(bytes / Math.max(1.0, THREADS.getCurrentThreadCpuTime() - c0));
            int n = rates.size();
            if (System.nanoTime() - w0 >= effort.warmUpMinNs() && n >= 10) {
                double last = median(rates.subList(n - 5, n).stream()
                        .mapToDouble(Double::doubleValue)
                        .toArray());
                double before = median(rates.subList(n - 10, n - 5).stream()
                        .mapToDouble(Double::doubleValue)
                        .toArray());
                if (last <= before * 1.05) {
                    break;
                }
            }
        }
        return System.nanoTime() - w0;
    }

    /** Reads and binds example 2 from memory, repeated for 200 ms, median of 9. */
    static Rate part21MbPerS(byte[] data, Effort effort) throws IOException, CamInputException {
        Run read = () -> {
            StepNcReader.read(new ByteArrayInputStream(data), "bench");
            return data.length;
        };
        warmUp(read, effort);
        double[] rates = new double[9];
        double[] cpuRates = new double[9];
        for (int r = 0; r < rates.length; r++) {
            long t0 = System.nanoTime();
            long c0 = THREADS.getCurrentThreadCpuTime();
            long bytes = 0;
            while (System.nanoTime() - t0 < WINDOW_NS) {
                bytes += read.once();
            }
            rates[r] = bytes / 1e6 / ((System.nanoTime() - t0) / 1e9);
            cpuRates[r] = bytes / 1e6 / ((THREADS.getCurrentThreadCpuTime() - c0) / 1e9);
        }
        return new Rate(median(rates), median(cpuRates));
    }

    /** Reads the 10 052-line corpus drawing and chains it, from memory, median of 7. */
    static Rate dxfMbPerS(byte[] data, Effort effort) throws IOException, CamInputException {
        warmUp(
                () -> {
                    Chainer.chain(
                            DxfReader.read(data, "bench", DxfReadOptions.DEFAULT)
                                    .curves(),
                            0.001);
                    return data.length;
                },
                effort);
        double[] rates = new double[7];
        double[] cpuRates = new double[7];
        for (int r = 0; r < rates.length; r++) {
            long t0 = System.nanoTime();
            long c0 = THREADS.getCurrentThreadCpuTime();
            DxfDrawing d = DxfReader.read(data, "bench", DxfReadOptions.DEFAULT);
            Chainer.chain(d.curves(), 0.001);
            rates[r] = data.length / 1e6 / ((System.nanoTime() - t0) / 1e9);
            cpuRates[r] = data.length / 1e6 / ((THREADS.getCurrentThreadCpuTime() - c0) / 1e9);
        }
        return new Rate(median(rates), median(cpuRates));
    }

    /** The parts of the generated sheet the cutting figure measures: a tenth of the 50 MB drawing's. */
    static final int CUT_SQUARES = 18_000;

    /**
     * Square parts cut per second: {@link SquareSheet} with {@code squares} parts written to a
     * temporary file, then read, planned (kerf 2 mm, arc leads 3 and 1 mm, rapids around cut
     * parts), posted and checked as {@code fresa cut} does, once after a warm-up on a sheet a tenth as
     * large; wall clock and this thread's CPU time.
     */
    static Rate cutPartsPerS(int squares) throws IOException, CamInputException {
        Path small = Files.createTempFile("fresa-bench-", "-squares.dxf");
        Path big = Files.createTempFile("fresa-bench-", "-squares.dxf");
        try {
            SquareSheet.write(small, Math.max(1, squares / 10));
            SquareSheet.write(big, squares);
            cutOnce(small);
            long t0 = System.nanoTime();
            long c0 = THREADS.getCurrentThreadCpuTime();
            int parts = cutOnce(big);
            double wall = (System.nanoTime() - t0) / 1e9;
            double cpu = (THREADS.getCurrentThreadCpuTime() - c0) / 1e9;
            return new Rate(parts / wall, parts / cpu);
        } finally {
            Files.deleteIfExists(small);
            Files.deleteIfExists(big);
        }
    }

    private static int cutOnce(Path dxf) throws IOException, CamInputException {
        JobSettings.CuttingSettings s = new JobSettings.CuttingSettings(
                dxf,
                2,
                org.fresa.cutting.CutProcess.PLASMA,
                3,
                1,
                org.fresa.cutting.LeadShape.ARC,
                org.fresa.cutting.CuttingOptions.DEFAULT_GAP_MM,
                org.fresa.dxf.DrawingUnits.AUTO,
                false,
                org.fresa.post.CuttingPost.LINUXCNC);
        // as fresa cut does it: the program posted to a file and checked there, never held as text
        Path ngc = dxf.resolveSibling(dxf.getFileName() + ".ngc");
        try {
            TaskOutcome o = CuttingService.run(s, ngc, false, ProgressMonitor.NONE);
            if (o.summary().containsKey("program_refused")) {
                throw new IllegalStateException("the program of the square sheet was refused: " + o.problems());
            }
            return ((Number) o.summary().get("outer")).intValue();
        } finally {
            Files.deleteIfExists(ngc);
        }
    }

    /** Recognition, passes and the 7M post of cavity 02 with the thesis's technology, in ms. */
    static double pocketMs() throws IOException, CamInputException {
        Path dad = inputFile(CAVITY02);
        try {
            return pocketMs(JobSettings.PocketSettings.DEFAULTS
                    .withContourFile(dad)
                    .withTechnology(new PocketTechnology(42, 0.74, 0.15, 23, 20, 5, 3000, 300, 100)));
        } finally {
            Files.deleteIfExists(dad);
        }
    }

    private static double pocketMs(JobSettings.PocketSettings s) throws IOException, CamInputException {
        double[] ms = new double[15];
        for (int r = -10; r < ms.length; r++) {
            long t0 = System.nanoTime();
            try {
                PocketService.program(PocketService.plan(s), PocketPost.LINUXCNC, "cavity02");
            } catch (org.fresa.pocket.ToolTooLargeException e) {
                throw new IllegalStateException(e.getMessage(), e);
            }
            if (r >= 0) {
                ms[r] = (System.nanoTime() - t0) / 1e6;
            }
        }
        return median(ms);
    }

    /**
     * {@code fresa robot} on example 2 with the IRB-140 in a fresh JVM, wall seconds, median of 3.
     * The JVM starts as the {@code ./fresa} launcher starts it: with the class-data archive next to
     * the jar when there is one newer than the jar (see {@link #javaCommand}).
     */
    static double processSeconds(Path jar) throws IOException, InterruptedException {
        Path example2 = inputFile(EXAMPLE2);
        try {
            return processSeconds(jar, example2);
        } finally {
            Files.deleteIfExists(example2);
        }
    }

    private static double processSeconds(Path jar, Path example2) throws IOException, InterruptedException {
        double[] s = new double[3];
        for (int r = 0; r < s.length; r++) {
            Path out = Files.createTempDirectory("fresa-bench");
            List<String> cmd = javaCommand(jar);
            cmd.addAll(List.of(
                    "robot",
                    example2.toString(),
                    "--robot",
                    "irb140",
                    "--robot-table",
                    "450,0,350",
                    "--table-piece",
                    "0,10,0",
                    "--out",
                    out.toString()));
            long t0 = System.nanoTime();
            Process p = new ProcessBuilder(cmd)
                    .redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .start();
            int rc = p.waitFor();
            s[r] = (System.nanoTime() - t0) / 1e9;
            try (var files = Files.list(out)) {
                for (Path f : files.toList()) {
                    Files.deleteIfExists(f);
                }
            }
            Files.deleteIfExists(out);
            if (rc > 1) {
                throw new IOException("fresa robot exited with " + rc);
            }
        }
        return median(s);
    }

    /** How the fresh JVM of the whole-process figure was started, for the figure's note. */
    private static String processNote(Path jar) {
        List<String> cmd = javaCommand(jar);
        if (!cmd.contains("-jar")) {
            return "the installed application's launcher " + cmd.get(0);
        }
        return cmd.stream().anyMatch(a -> a.startsWith("-XX:Shared"))
                ? "with the class-data archive " + jar.resolveSibling("fresa.jsa") + ", as ./fresa starts"
                : "without a class-data archive (./fresa makes " + jar.resolveSibling("fresa.jsa") + ")";
    }

    /**
     * The command line that starts the jar as {@code ./fresa} does: this JVM's java, and
     * {@code fresa.jsa} beside the jar as the class-data archive when it is newer than the jar
     * (the JVM ignores an archive that does not match, silently). In an installed app image, whose
     * runtime has no {@code java} command, the application's own launcher (jpackage names it in
     * {@code jpackage.app-path}) starts the fresh JVM, as the user starts it.
     */
    static List<String> javaCommand(Path jar) {
        List<String> cmd = new ArrayList<>();
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        String launcher = System.getProperty("jpackage.app-path");
        if (!Files.isExecutable(java) && launcher != null) {
            cmd.add(launcher);
            return cmd;
        }
        cmd.add(java.toString());
        Path jsa = jar.resolveSibling("fresa.jsa");
        try {
            if (Files.isRegularFile(jsa)
                    && Files.getLastModifiedTime(jsa).compareTo(Files.getLastModifiedTime(jar)) >= 0) {
                cmd.addAll(List.of("-XX:SharedArchiveFile=" + jsa, "-Xlog:cds=off", "-Xlog:cds+dynamic=off"));
            }
        } catch (IOException e) {
            // no usable archive: start without one, as the launcher does
        }
        cmd.addAll(List.of("-jar", jar.toString()));
        return cmd;
    }

    /** The figures as an aligned table for people. */
    public static String table(Map<String, Object> figures) {
        StringBuilder sb = new StringBuilder(
                String.format(java.util.Locale.ROOT, "%-34s %14s %10s  %s%n", "figure", "measured", "goal", "met"));
        @SuppressWarnings("unchecked")
        Map<String, Object> met = (Map<String, Object>) figures.get("met");
        for (Map.Entry<String, Object> e : figures.entrySet()) {
            if (!(e.getValue() instanceof Double) && e.getValue() != null) {
                continue;
            }
            Double goal = GOALS.get(e.getKey());
            Object m = met.get(e.getKey());
            sb.append(String.format(
                    java.util.Locale.ROOT,
                    "%-34s %14s %10s  %s%n",
                    e.getKey(),
                    e.getValue() == null ? "n/a" : String.format(java.util.Locale.ROOT, "%.3f", (Double) e.getValue()),
                    goal == null ? "" : (e.getKey().endsWith("_per_s") ? ">= " : "<= ") + goal,
                    m == null ? "" : ((Boolean) m ? "yes" : "NO")));
        }
        return sb.toString();
    }
}
