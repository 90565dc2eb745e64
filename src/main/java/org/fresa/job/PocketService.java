package org.fresa.job;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.CamInputException;
import org.fresa.model.ContourFile;
import org.fresa.model.Toolpath;
import org.fresa.pocket.DadReader;
import org.fresa.pocket.PassPlanner;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketProfile;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.PocketToolpath;
import org.fresa.pocket.Recognition;
import org.fresa.pocket.ToolTooLargeException;
import org.fresa.post.NcPost;
import org.fresa.post.NcPosts;
import org.fresa.post.Sinumerik7MPost;

/**
 * The pocket module's service, shared by {@code fresa pocket} and {@code fresa run}: reads the
 * contour ({@code .dad} or {@code .contour}), builds the recognition tree, plans the passes and
 * writes the NC program for the chosen post.
 */
public final class PocketService {

    /** The thesis's own dialect, written by this module; every other post comes from {@link NcPosts}. */
    public static final List<String> SINUMERIK_7M_POSTS = List.of("7m-compat", "7m");

    /** Most elements a pocket contour may have: the recognition compares elements pairwise at each event. */
    public static final int MAX_ELEMENTS = 2000;

    private PocketService() {
    }

    /** Reads a contour file by its extension. */
    public static PocketProfile readContour(Path file) throws CamInputException, IOException {
        String name = file.getFileName().toString();
        String lower = name.toLowerCase(Locale.ROOT);
        String text = Files.readString(file, StandardCharsets.ISO_8859_1);
        if (lower.endsWith(".dad")) {
            return DadReader.read(text, file.toString());
        }
        List<org.fresa.geom.Contour> contours;
        if (lower.endsWith(".dxf")) {
            DrawingContours drawing = DrawingContours.read(file);
            if (drawing.openChains() > 0) {
                throw new CamInputException(file.toString(), drawing.openChains()
                        + " open chain(s) in the drawing: a pocket needs one closed contour");
            }
            contours = drawing.closed();
        } else {
            contours = ContourFile.read(new StringReader(text), file.toString());
        }
        if (contours.isEmpty()) {
            throw new CamInputException(file.toString(), "no contour in the file");
        }
        if (contours.size() > 1) {
            // milling through an island silently would be worse than refusing
            throw new CamInputException(file.toString(), "islands (inner contours) are not supported yet: "
                    + (contours.size() - 1) + " found");
        }
        if (contours.get(0).size() > MAX_ELEMENTS) {
            throw new CamInputException(file.toString(), "the contour has " + contours.get(0).size()
                    + " elements; pocket milling takes at most " + MAX_ELEMENTS + " (simplify the drawing)");
        }
        try {
            return PocketProfile.fromContours(contours);
        } catch (IllegalArgumentException e) {
            // a contour the pocket model cannot take (one full circle, elements that vanish when merged)
            throw new CamInputException(file.toString(), e.getMessage());
        }
    }

    /** The plan for the settings (no file written). */
    public static PocketPlan plan(PocketSettings s) throws CamInputException, IOException, ToolTooLargeException {
        return plan(s, s.post().equals("7m-compat"));
    }

    /** The plan for the settings; faithful: the thesis's pass rules exactly. */
    public static PocketPlan plan(PocketSettings s, boolean faithful)
            throws CamInputException, IOException, ToolTooLargeException {
        PocketTechnology tech;
        try {
            tech = new PocketTechnology(s.toolDiameterMm(), s.cutFraction(), s.finishFraction(), s.zTopMm(),
                    s.zBottomMm(), s.maxDepthPerPassMm(), s.spindleRpm(), s.feedMmPerMin(), s.finishFeedMmPerMin());
        } catch (IllegalArgumentException e) {
            throw new CamInputException("technology", e.getMessage());
        }
        PocketProfile profile = readContour(s.contour());
        Recognition.Result rec = Recognition.of(profile);
        return PassPlanner.plan(rec, tech, faithful);
    }

    /** The NC program text for a plan. */
    public static String program(PocketPlan plan, String post, String programName) throws IOException {
        switch (post) {
            case "7m-compat":
                return new Sinumerik7MPost(Sinumerik7MPost.Mode.COMPAT).write(plan);
            case "7m":
                return new Sinumerik7MPost(Sinumerik7MPost.Mode.CORRECTED).write(plan);
            default: {
                NcPost p = NcPosts.byName(post).orElseThrow(() -> new IllegalArgumentException(post));
                StringWriter w = new StringWriter();
                p.write(PocketToolpath.of(plan, true), programName, w);
                return w.toString();
            }
        }
    }

    /** Runs the pocket job and writes the NC program to outFile. */
    public static TaskOutcome run(PocketSettings s, Path outFile, ProgressMonitor progress)
            throws CamInputException, IOException {
        List<String> problems = new ArrayList<>();
        if (!SINUMERIK_7M_POSTS.contains(s.post()) && NcPosts.byName(s.post()).isEmpty()) {
            throw new CamInputException("--post", "unknown post '" + s.post() + "': expected 7m-compat, 7m or "
                    + String.join(", ", NcPosts.names()));
        }
        PocketPlan plan;
        try {
            plan = plan(s);
        } catch (ToolTooLargeException e) {
            return new TaskOutcome(1, List.of(e.getMessage()), Map.of(), List.of());
        }
        Recognition.Result rec = plan.recognition();
        double a = s.finishFraction() * s.toolDiameterMm();
        if (rec.maxToolDiameterMm() < s.toolDiameterMm() + a + 0.1) {
            problems.add("warning: the tool does not pass every bottleneck (DIAMETRO MAXIMO "
                    + String.format(Locale.ROOT, "%.3f", rec.maxToolDiameterMm()) + " mm)");
        }
        String name = s.contour().getFileName().toString();
        String nc = program(plan, s.post(), name);
        AtomicFiles.writeString(outFile, nc);
        Toolpath path = PocketToolpath.of(plan, !s.post().startsWith("7m"));
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("contour", s.contour().toString());
        summary.put("post", s.post());
        summary.put("leaf_offsets", rec.leafOffsets());
        summary.put("max_hole_diameter", rec.maxHoleDiameterMm());
        summary.put("max_tool_diameter", rec.maxToolDiameterMm());
        summary.put("wall_tool_diameter", rec.wallToolDiameterMm());
        summary.put("passes", plan.milled().size());
        summary.put("pass_offsets", plan.generated().stream().map(p -> p.offsetMm()).toList());
        summary.put("depth_passes", plan.technology().depthPasses());
        summary.put("path_length_mm", PocketToolpath.lengthMm(path));
        summary.put("out", outFile.toString());
        return new TaskOutcome(0, problems, summary, List.of(outFile));
    }
}
