package org.fresa.post;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.geom.Vec3;

/**
 * Test helper: runs LinuxCNC's interpreter on a program and reads its canonical motions back into
 * workpiece-frame values. The interpreter is the project's own {@code tools/rs274}, which fetches
 * it from the Debian/Ubuntu archive into a cache on first use; {@code ../shared/tools/rs274}
 * beside the checkout serves only when ours cannot set it up. Tests skip, saying why, when
 * neither can.
 */
public final class Rs274 {

    /** The project's script. */
    static final Path OWN = Path.of("tools/rs274");

    /** The one beside the checkout, a fallback only. */
    static final Path SHARED = Path.of("../shared/tools/rs274");

    private static final Pattern CALL =
            Pattern.compile("(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|SELECT_PLANE|DWELL)\\((.*)\\)");

    /** The script to run, or null; and why not, when null. Decided once per test JVM. */
    private static Path tool;

    private static String whyNot;

    private Rs274() {}

    /**
     * Whether an interpreter can run here: {@code tools/rs274 --fetch} sets ours up (the first
     * time it downloads the package, up to a few minutes); the shared one is the fallback.
     */
    public static synchronized boolean available() {
        if (tool == null && whyNot == null) {
            String own = fetch(OWN);
            if (own == null) {
                tool = OWN;
            } else if (Files.isExecutable(SHARED)) {
                tool = SHARED;
            } else {
                whyNot = "LinuxCNC's interpreter could not be set up: " + own;
            }
        }
        return tool != null;
    }

    /** Why {@link #available()} is false, for the skip message. */
    public static synchronized String whyNot() {
        return available() ? "" : whyNot;
    }

    /** Runs {@code script --fetch}: null when the interpreter is ready, else what it said. */
    private static String fetch(Path script) {
        if (!Files.isExecutable(script)) {
            return script + " is not here (run the tests from the project's folder)";
        }
        try {
            Path log = Files.createTempFile("rs274-fetch", ".txt");
            try {
                Process p = new ProcessBuilder(script.toString(), "--fetch")
                        .redirectErrorStream(true)
                        .redirectOutput(log.toFile())
                        .start();
                if (!p.waitFor(10, TimeUnit.MINUTES)) {
                    p.destroyForcibly();
                    return script + " --fetch took more than 10 minutes";
                }
                return p.exitValue() == 0
                        ? null
                        : Files.readString(log, StandardCharsets.UTF_8).strip();
            } finally {
                Files.deleteIfExists(log);
            }
        } catch (IOException e) {
            return script + ": " + e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        }
    }

    /** What the interpreter did with a program. */
    public record Result(int exitStatus, String stdout, String stderr, List<Canon> motions) {}

    /**
     * One canonical motion. For arcs, centre is the axis point at the start's height along the
     * normal, normal is +Z/+Y/+X for the XY/XZ/YZ plane, rotation as printed (sign = sense about
     * the normal, magnitude = turns + 1). A DWELL is kind "dwell" at the position the previous
     * motion reached (the origin before any), with its time in seconds.
     */
    public record Canon(String kind, Vec3 end, Vec3 center, Vec3 normal, int rotation, double seconds) {

        public Canon(String kind, Vec3 end, Vec3 center, Vec3 normal, int rotation) {
            this(kind, end, center, normal, rotation, 0);
        }
    }

    /**
     * Runs the interpreter on a program; a tool diameter of 0 or less leaves the tool table's
     * default. The interpreter binary itself has been seen to die with a bus error on a loaded
     * machine (a crash of the interpreter, not a verdict on the program): such a run is repeated,
     * up to three times, so that only the controller's own answers decide a test.
     */
    public static Result run(Path program, double toolDiameterMm) throws IOException, InterruptedException {
        Result r = null;
        for (int attempt = 0; attempt < 3; attempt++) {
            r = runOnce(program, toolDiameterMm);
            if (!crashed(r)) {
                return r;
            }
        }
        return r;
    }

    /** Whether the interpreter process died of a signal (bash reports it on the script's stderr). */
    static boolean crashed(Result r) {
        return r.exitStatus() != 0 && CRASH.matcher(r.stderr()).find();
    }

    private static final Pattern CRASH =
            Pattern.compile("Bus error|Segmentation fault|core dumped|Aborted|Illegal instruction");

    private static Result runOnce(Path program, double toolDiameterMm) throws IOException, InterruptedException {
        Path outFile = Files.createTempFile("rs274", ".out");
        Path errFile = Files.createTempFile("rs274", ".err");
        try {
            if (!available()) {
                throw new IOException(whyNot());
            }
            List<String> cmd = new ArrayList<>(List.of(tool.toString()));
            if (toolDiameterMm > 0) {
                cmd.addAll(List.of("--tool-diameter", Double.toString(toolDiameterMm)));
            }
            cmd.add(program.toString());
            Process p = new ProcessBuilder(cmd)
                    .redirectOutput(outFile.toFile())
                    .redirectError(errFile.toFile())
                    .start();
            if (!p.waitFor(120, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new IOException("rs274 did not finish");
            }
            String out = Files.readString(outFile, StandardCharsets.UTF_8);
            String err = Files.readString(errFile, StandardCharsets.UTF_8);
            return new Result(p.exitValue(), out, err, parse(out));
        } finally {
            Files.deleteIfExists(outFile);
            Files.deleteIfExists(errFile);
        }
    }

    /** The interpreter's last words, for a failure message: stderr, then the tail of stdout. */
    public static String log(Result r) {
        String out = r.stdout().length() > 800 ? r.stdout().substring(r.stdout().length() - 800) : r.stdout();
        return r.stderr() + "\n" + out;
    }

    static List<Canon> parse(String out) {
        List<Canon> list = new ArrayList<>();
        String plane = "CANON_PLANE_XY";
        for (String line : out.split("\n")) {
            Matcher m = CALL.matcher(line);
            if (!m.find()) {
                continue;
            }
            String[] a = m.group(2).split(",\\s*");
            switch (m.group(1)) {
                case "SELECT_PLANE" -> plane = a[0].trim();
                case "DWELL" ->
                    list.add(new Canon(
                            "dwell",
                            list.isEmpty()
                                    ? Vec3.ZERO
                                    : list.get(list.size() - 1).end(),
                            null,
                            null,
                            0,
                            d(a[0])));
                case "STRAIGHT_TRAVERSE", "STRAIGHT_FEED" ->
                    list.add(new Canon(
                            m.group(1).equals("STRAIGHT_FEED") ? "feed" : "rapid",
                            new Vec3(d(a[0]), d(a[1]), d(a[2])),
                            null,
                            null,
                            0));
                default -> {
                    double e1 = d(a[0]);
                    double e2 = d(a[1]);
                    double c1 = d(a[2]);
                    double c2 = d(a[3]);
                    int rot = Integer.parseInt(a[4].trim());
                    double ax = d(a[5]);
                    Vec3 end;
                    Vec3 cen;
                    Vec3 n;
                    switch (plane) {
                        case "CANON_PLANE_XZ" -> {
                            end = new Vec3(e2, ax, e1);
                            cen = new Vec3(c2, 0, c1);
                            n = Vec3.UNIT_Y;
                        }
                        case "CANON_PLANE_YZ" -> {
                            end = new Vec3(ax, e1, e2);
                            cen = new Vec3(0, c1, c2);
                            n = Vec3.UNIT_X;
                        }
                        default -> {
                            end = new Vec3(e1, e2, ax);
                            cen = new Vec3(c1, c2, 0);
                            n = Vec3.UNIT_Z;
                        }
                    }
                    list.add(new Canon("arc", end, cen, n, rot));
                }
            }
        }
        return list;
    }

    private static double d(String s) {
        return Double.parseDouble(s.trim());
    }
}
