package org.fresa.job;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.fresa.cutting.CutOrderOverride;
import org.fresa.cutting.CutPath;
import org.fresa.cutting.CutPlan;
import org.fresa.cutting.CutPlanner;
import org.fresa.cutting.CutProcess;
import org.fresa.cutting.CuttingOptions;
import org.fresa.cutting.KerfCompensation;
import org.fresa.cutting.LeadShape;
import org.fresa.dxf.DxfDrawing;
import org.fresa.dxf.DxfReadOptions;
import org.fresa.dxf.DxfReader;
import org.fresa.io.AtomicFiles;
import org.fresa.io.Json;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.model.CamInputException;
import org.fresa.post.CuttingPost;
import org.fresa.post.SheetCuttingPost;

/**
 * The sheet cutting task behind {@code fresa cut}, {@code fresa run} (task cut) and the Cutting
 * tab: reads the DXF, plans the cut and writes the program.
 */
public final class CuttingService {

    /** Rapid traverse assumed for the time estimate (mm/min). */
    static final double RAPID_MM_PER_MIN = 10_000;

    private CuttingService() {}

    /**
     * The drawing and the plan of one run, and what its program is written with. The program text
     * is not held: {@link #writeProgram} posts it block by block (to the file, for a big sheet);
     * {@link #program()} makes it whole, for the GUI's view of it and for tests.
     *
     * @param programName the drawing's file name, in the program's first comment
     */
    public record Result(
            DxfDrawing drawing, CutPlan plan, CuttingOptions options, CuttingPost dialect, String programName) {

        /** Posts the program to {@code out}, a cut at a time. */
        public void writeProgram(Writer out) throws IOException {
            List<Integer> comp = new ArrayList<>(plan.cuts().size());
            for (CutPath c : plan.cuts()) {
                comp.add(c.compensation());
            }
            SheetCuttingPost.write(
                    plan.sections(),
                    programName,
                    new SheetCuttingPost.Job(options.process().id(), options.pierceDwellS(), comp, options.kerfMm()),
                    dialect,
                    out);
        }

        /** The whole program text. */
        public String program() {
            StringBuilderWriter w = new StringBuilderWriter();
            try {
                writeProgram(w);
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
            return w.toString();
        }
    }

    /** Checks the settings and converts them to planner options (the gap tolerance still in drawing units). */
    public static CuttingOptions options(CuttingSettings s) throws CamInputException {
        CutProcess p = s.process();
        if (!(s.kerfMm() >= 0)
                || !(s.leadInMm() >= 0)
                || !(s.leadOutMm() >= 0)
                || !(s.toleranceMm() >= 0)
                || !Double.isFinite(s.kerfMm() + s.leadInMm() + s.leadOutMm() + s.toleranceMm())) {
            throw new CamInputException("options", "kerf, lead lengths and tolerance must be finite and >= 0");
        }
        if (!(s.overcutMm() >= 0) || !Double.isFinite(s.overcutMm())) {
            throw new CamInputException("--overcut", "the overcut must be finite and >= 0");
        }
        boolean outerCw = s.outerDirection().clockwise(p.outerClockwise());
        boolean holesCw = s.holeDirection().clockwise(!outerCw);
        try {
            return CuttingOptions.of(p, s.kerfMm(), s.leadInMm(), s.leadOutMm(), s.lead() == LeadShape.ARC)
                    .withGapTolerance(s.toleranceMm())
                    .withPaperMode(s.paperMode())
                    .withControllerCompensation(s.compensation() == KerfCompensation.CONTROLLER)
                    .withOvercut(s.overcutMm())
                    .withDirections(outerCw, holesCw)
                    .withAvoidCutParts(s.avoidCutParts());
        } catch (IllegalArgumentException e) {
            throw new CamInputException("options", e.getMessage());
        }
    }

    /** Reads and plans without writing anything. */
    public static Result compute(CuttingSettings s, ProgressMonitor progress) throws CamInputException, IOException {
        return compute(s, false, progress);
    }

    /**
     * Reads and plans without writing anything.
     *
     * @param toleranceInDrawingUnits the settings' gap tolerance is in drawing units (the command
     *     line's {@code --tolerance}), not millimetres (job files, the default {@link CuttingOptions#DEFAULT_GAP_MM})
     */
    public static Result compute(CuttingSettings s, boolean toleranceInDrawingUnits, ProgressMonitor progress)
            throws CamInputException, IOException {
        CuttingOptions o = options(s);
        CuttingPost dialect = s.post();
        progress.progress(0.05, "reading " + s.drawing().getFileName());
        DxfDrawing d = DxfReader.read(
                s.drawing(), DxfReadOptions.DEFAULT.withUnits(s.units().units()));
        progress.checkCancelled();
        progress.progress(0.3, "planning");
        CutPlan plan;
        try {
            plan = CutPlanner.plan(
                    d.layers(),
                    o.withGapTolerance(s.toleranceMm() * (toleranceInDrawingUnits ? d.mmPerUnit() : 1)),
                    s.cutOrder(),
                    (f, step) -> progress.progress(0.3 + 0.55 * f, step));
        } catch (CutOrderOverride.Refused e) {
            throw new CamInputException("cutOrder", e.getMessage());
        }
        progress.checkCancelled();
        return new Result(d, plan, o, dialect, s.drawing().getFileName().toString());
    }

    /** Runs the task and writes the program to the given file (atomically). */
    public static TaskOutcome run(
            CuttingSettings s, Path outFile, boolean toleranceInDrawingUnits, ProgressMonitor progress)
            throws CamInputException, IOException {
        Result r = compute(s, toleranceInDrawingUnits, progress);
        if (r.plan().cuts().isEmpty()) {
            // a program that cuts nothing is no partial result: nothing is written
            return outcome(r, List.of());
        }
        progress.progress(0.9, "writing and checking the program");
        String file = outFile.getFileName().toString();
        try {
            AtomicFiles.write(outFile, out -> write(r, out), written -> check(r, file, written));
        } catch (ProgramChecks.RefusedProgram e) {
            return refused(outcome(r, List.of()), e);
        }
        return outcome(r, List.of(outFile.toAbsolutePath()));
    }

    /** Runs the task for a job, writing {@code program.ngc} into the output folder. */
    public static TaskOutcome run(CuttingSettings s, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        Result r = compute(s, progress);
        out.create();
        if (r.plan().cuts().isEmpty()) {
            // a program that cuts nothing is no partial result: the summary says why
            return outcome(r, List.of(out.writeString("summary.json", Json.write(summary(r)))));
        }
        String file = programFile(r);
        progress.progress(0.9, "writing and checking the program");
        Path p;
        try {
            p = out.write(file, o -> write(r, o), written -> check(r, file, written));
        } catch (ProgramChecks.RefusedProgram e) {
            Path j = out.writeString("summary.json", Json.write(summary(r)));
            return refused(outcome(r, List.of(j)), e);
        }
        Path j = out.writeString("summary.json", Json.write(summary(r)));
        return outcome(r, List.of(p, j));
    }

    /** The name of the program a job's run writes into its folder: {@code program.mpf} for the 840D, else {@code program.ngc}. */
    public static String programFile(Result r) {
        return r.dialect() == CuttingPost.SIEMENS_840D ? "program.mpf" : "program.ngc";
    }

    /**
     * What a run says of a plan besides the program check, in its words and order: the drawing's
     * warnings, the plan's (each contour not cut, each open chain), and that there is nothing to
     * cut when no contour closes.
     */
    public static List<String> problems(Result r) {
        List<String> all = new ArrayList<>(r.drawing().warnings());
        // every one: a contour not cut that the planner is not told of is a part missing from the sheet
        all.addAll(r.plan().warnings());
        if (r.plan().cuts().isEmpty()) {
            all.add("nothing to cut: the drawing has no closed contour");
        }
        return all;
    }

    /**
     * Why the program check refuses the result's program under this file name, in the words a
     * run says it ("program.ngc not written: it fails the program check at line ..."); empty
     * when the program passes and is written.
     */
    public static java.util.Optional<String> refusal(Result r, String file) {
        try {
            check(r, file);
            return java.util.Optional.empty();
        } catch (ProgramChecks.RefusedProgram e) {
            return java.util.Optional.of(e.getMessage());
        }
    }

    /**
     * Checks the program as the machine would run it: every cutting move with the process's jet on,
     * every word in range.
     */
    public static void check(Result r, String file) throws ProgramChecks.RefusedProgram {
        ProgramChecks.require(
                file, r.program(), ProgramChecks.dialect(r.dialect().id()), limits(r));
    }

    /**
     * Checks the written program file block by block, before it is renamed into place: the
     * program of a big sheet is never held as text.
     */
    static void check(Result r, String file, Path written) throws ProgramChecks.RefusedProgram, IOException {
        ProgramChecks.require(file, written, ProgramChecks.dialect(r.dialect().id()), limits(r));
    }

    /** Posts the program as UTF-8 (the post writes ASCII), a buffer at a time. */
    private static void write(Result r, java.io.OutputStream out) throws IOException {
        Writer w = new java.io.OutputStreamWriter(out, java.nio.charset.StandardCharsets.UTF_8);
        r.writeProgram(w);
        w.flush();
    }

    /** The limits of a sheet-cutting program: the process's on and off words instead of a spindle. */
    public static org.fresa.check.Limits limits(Result r) {
        String[] jet =
                SheetCuttingPost.jetWords(r.dialect(), r.options().process().id());
        return org.fresa.check.Limits.sheetCutting(r.options().process().id(), jet[0], jet[1]);
    }

    private static TaskOutcome refused(TaskOutcome o, ProgramChecks.RefusedProgram e) {
        List<String> problems = new ArrayList<>(o.problems());
        problems.add(e.getMessage());
        Map<String, Object> summary = new LinkedHashMap<>(o.summary());
        summary.put("program_refused", e.failure().message());
        return new TaskOutcome(1, problems, summary, o.files());
    }

    /** The JSON summary (spec/cli.md: contours, outer, inner, open, pierces, lengths, warnings). */
    public static Map<String, Object> summary(Result r) {
        CutPlan p = r.plan();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("contours", p.outers().size() + p.holes().size());
        m.put("outer", p.outers().size());
        m.put("inner", p.holes().size());
        m.put("open", p.open().size());
        m.put("pierces", p.cuts().size());
        m.put("cut_length_mm", round(p.cutLengthMm()));
        m.put("rapid_length_mm", round(p.rapidLengthMm()));
        double time = p.cutLengthMm() / r.options().feedMmPerMin() * 60
                + p.rapidLengthMm() / RAPID_MM_PER_MIN * 60
                + p.cuts().size() * r.options().pierceDwellS();
        m.put("estimated_time_s", round(time));
        m.put("not_cut", p.uncut().size());
        m.put("duplicates_removed", p.duplicates());
        m.put("zero_length_removed", p.zeroLength());
        m.put("invalid_vertices", p.invalidVertices().size());
        List<Object> notCut = new ArrayList<>();
        for (CutPlan.NotCut n : p.notCut()) {
            org.fresa.geom.Box2 b = n.contour().bounds();
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("contour", n.label());
            e.put("x_mm", round(b.minX()));
            e.put("y_mm", round(b.minY()));
            e.put("width_mm", round(b.width()));
            e.put("height_mm", round(b.height()));
            e.put("reason", n.reason());
            notCut.add(e);
        }
        for (List<org.fresa.geom.Curve2> chain : p.open()) {
            org.fresa.geom.Vec2 a = chain.get(0).start();
            org.fresa.geom.Vec2 z = chain.get(chain.size() - 1).end();
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("contour", "open chain of " + chain.size() + " elements");
            e.put("x_mm", round(a.x()));
            e.put("y_mm", round(a.y()));
            e.put("to_x_mm", round(z.x()));
            e.put("to_y_mm", round(z.y()));
            e.put("reason", "open: its ends do not meet within the gap tolerance");
            notCut.add(e);
        }
        // each contour not cut, with its place (lower left corner of its box) and why
        m.put("not_cut_contours", notCut);
        List<Object> invalid = new ArrayList<>();
        for (org.fresa.geom.Vec2 v : p.invalidVertices()) {
            invalid.add(List.of(round(v.x()), round(v.y())));
        }
        m.put("invalid_vertex_points", invalid);
        m.put("units", r.drawing().units().name().toLowerCase(Locale.ROOT));
        m.put("process", r.options().process().id());
        m.put("kerf_mm", r.options().kerfMm());
        m.put("post", r.dialect().id());
        m.put("compensation", r.options().controllerCompensation() ? "controller" : "software");
        m.put("outer_direction", r.options().outerClockwise() ? "cw" : "ccw");
        m.put("hole_direction", r.options().holesClockwise() ? "cw" : "ccw");
        m.put("overcut_mm", r.options().overcutMm());
        long detours = p.rapids().stream().filter(x -> x.size() > 2).count();
        m.put("rapid_detours", detours);
        m.put("ignored", new LinkedHashMap<>(r.drawing().ignored()));
        List<String> w = new ArrayList<>(r.drawing().warnings());
        w.addAll(p.warnings());
        m.put("warnings", w);
        return m;
    }

    private static double round(double v) {
        return Math.round(v * 1000) / 1000.0;
    }

    private static TaskOutcome outcome(Result r, List<Path> files) {
        CutPlan p = r.plan();
        int status = p.cuts().isEmpty() || !p.uncut().isEmpty() ? 1 : 0;
        return new TaskOutcome(status, problems(r), summary(r), files);
    }

    /** A Writer into a StringBuilder without synchronisation. */
    private static final class StringBuilderWriter extends Writer {
        private final StringBuilder sb = new StringBuilder(1 << 16);

        @Override
        public void write(char[] cbuf, int off, int len) {
            sb.append(cbuf, off, len);
        }

        @Override
        public void write(String str) {
            sb.append(str);
        }

        @Override
        public void flush() {}

        @Override
        public void close() {}

        @Override
        public String toString() {
            return sb.toString();
        }
    }
}
