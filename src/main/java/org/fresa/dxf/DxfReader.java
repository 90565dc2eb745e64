package org.fresa.dxf;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.DoubleFunction;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;
import org.fresa.model.FileChecks;

/**
 * Reads the model space of a DXF drawing (ASCII R12 to R2018, or binary) into lines and exact
 * arcs per layer, in millimetres.
 *
 * <p>Read: LINE, ARC, CIRCLE, LWPOLYLINE and POLYLINE/VERTEX (the bulge at vertex i belongs to
 * the segment from vertex i to i + 1), ELLIPSE and SPLINE (replaced by arcs within
 * {@link DxfReadOptions#curveToleranceMm()}), INSERT and MINSERT with nested blocks, scale,
 * rotation and mirroring (depth bounded, a block inserting itself is reported once), OCS
 * extrusions ((0, 0, -1) mirrors x), {@code $INSUNITS}. An ELLIPSE whose axis ratio is above 1
 * (QCAD writes the longer axis as the minor one) is read with its axes swapped, as AutoCAD does.
 * Skipped, counted and named in one warning per kind (how many, where the first is): text,
 * hatches, dimensions, images, points, paper space, frozen or switched-off layers and every
 * other type.
 *
 * <p>An entity that cannot be used (a circle of radius 0, a spline whose knots do not match its
 * control points) is named in {@link DxfDrawing#warnings()} by type, handle and line; the rest
 * of the drawing is read. The drawing is refused ({@link DxfException}, with the line) when the
 * file itself is broken, since cutting the sheet without the entity would make a wrong part: a
 * numeric group that is not a finite number, a coordinate missing from an entity, a file that
 * ends without its {@code 0 EOF}, or a drawing past the limits of {@link DxfReadOptions}.
 */
public final class DxfReader {

    private static final Set<String> QUIET = Set.of("SEQEND", "ENDBLK", "VIEWPORT");
    /** Entity visits (inserts expanded) after which the rest of the drawing is left out. */
    static final long MAX_VISITS = 4_000_000;
    /** Per-entity warnings kept; the rest are counted in one last warning. */
    static final int MAX_WARNINGS = 1000;
    /** Coordinates (mm) beyond this are refused: their squares would overflow the geometry. */
    static final double MAX_COORDINATE_MM = 1e9;

    private final DxfTags tags;
    private final DxfReadOptions opt;
    private final List<String> warnings = new ArrayList<>();
    private final Map<String, Integer> ignored = new TreeMap<>();
    private final Map<String, Entity> firstIgnored = new HashMap<>();
    private final Map<String, List<Curve2>> layers = new LinkedHashMap<>();
    private final Map<String, Block> blocks = new HashMap<>();
    private final Set<String> hiddenLayers = new HashSet<>();
    private final Set<String> reportedCycles = new HashSet<>();
    private int curveCount;
    /** Entities visited while expanding inserts: bounds the work of nested arrays of empty blocks. */
    private long visits;

    private int warningsLeftOut;
    private boolean truncated;
    private Integer insUnits;
    private Integer measurement;

    /** One entity: its tags are [first, end) of the tag list, after the (0, TYPE) tag. */
    private record Entity(String type, int index, int first, int end, List<Entity> children) {}

    private record Block(String name, Vec2 base, List<Entity> entities) {}

    private DxfReader(DxfTags tags, DxfReadOptions opt) {
        this.tags = tags;
        this.opt = opt;
    }

    /** Reads a file with the default options. */
    public static DxfDrawing read(Path file) throws DxfException, IOException {
        return read(file, DxfReadOptions.DEFAULT);
    }

    /**
     * Reads a drawing file.
     *
     * @throws DxfException also for a path that is not a regular file, or a file larger than
     *     {@link #maxFileBytes()}
     */
    public static DxfDrawing read(Path file, DxfReadOptions opt) throws DxfException, IOException {
        String name = file.getFileName() == null
                ? file.toString()
                : file.getFileName().toString();
        try {
            FileChecks.requireInput(file, "a DXF drawing", maxFileBytes());
        } catch (DxfException e) {
            throw e;
        } catch (CamInputException e) {
            throw new DxfException(e.source(), 0, e.problem());
        }
        return new DxfReader(DxfTags.parse(file, name), opt).run();
    }

    /**
     * The largest drawing read: its group codes and values are held in memory (about 2.5 times
     * the file's size for a drawing of LINEs, read line by line, never as one string), then its
     * lines and arcs and what cutting builds from them, so an eighth of the Java heap (64 MB in
     * 512 MB).
     */
    public static long maxFileBytes() {
        return FileChecks.heapShare(8);
    }

    /**
     * Reads a drawing from its bytes.
     *
     * @param source the name used in messages
     * @throws DxfException when the bytes are not a DXF group-code stream
     */
    public static DxfDrawing read(byte[] data, String source, DxfReadOptions opt) throws DxfException {
        DxfReader r = new DxfReader(DxfTags.parse(data, source), opt);
        return r.run();
    }

    private DxfDrawing run() throws DxfException {
        List<Entity> entities = new ArrayList<>();
        int i = 0;
        boolean sawSection = false;
        while (i < tags.size) {
            if (tags.code(i) == 0 && tags.valueIs(i, "SECTION")) {
                sawSection = true;
                String name = i + 1 < tags.size && tags.code(i + 1) == 2 ? tags.value(i + 1) : "";
                int j = i + 2;
                int end = j;
                while (end < tags.size && !(tags.code(end) == 0 && tags.valueIs(end, "ENDSEC"))) {
                    end++;
                }
                switch (name) {
                    case "HEADER" -> header(j, end);
                    case "TABLES" -> tables(j, end);
                    case "BLOCKS" -> blocks(j, end);
                    case "ENTITIES" -> entities.addAll(entityList(j, end));
                    default -> {}
                }
                i = end + 1;
            } else {
                i++;
            }
        }
        if (!sawSection) {
            throw new DxfException(tags.source, 1, "not a DXF drawing: no SECTION found");
        }
        DxfUnits units = units();
        double mm = units == DxfUnits.UNITLESS ? opt.unitlessAs().mm() : units.mm();
        DxfAffine root = DxfAffine.scale(mm, mm);
        for (Entity e : entities) {
            convert(e, root, null, 0, new ArrayDeque<>());
        }
        if (truncated) {
            throw new DxfException(
                    tags.source,
                    0,
                    "the drawing expands to more than " + opt.maxCurves()
                            + " lines and arcs (the limit of one drawing; ellipses and splines count as the arcs replacing"
                            + " them): refused rather than cut without the rest; split the drawing");
        }
        if (warningsLeftOut > 0) {
            warnings.add(warningsLeftOut + " more warnings like the ones above are left out");
        }
        ignoredWarnings();
        return new DxfDrawing(tags.source, units, mm, layers, warnings, ignored);
    }

    private DxfUnits units() {
        if (opt.units().isPresent()) {
            return opt.units().get();
        }
        if (insUnits == null || insUnits == 0) {
            warnings.add("the drawing declares no units ($INSUNITS " + (insUnits == null ? "absent" : "0")
                    + (measurement != null ? ", $MEASUREMENT " + measurement : "") + "): read as "
                    + opt.unitlessAs().name().toLowerCase(Locale.ROOT));
            return DxfUnits.UNITLESS;
        }
        Optional<DxfUnits> u = DxfUnits.ofCode(insUnits);
        if (u.isEmpty()) {
            warnings.add("$INSUNITS " + insUnits + " is not a unit Fresa scales: read as "
                    + opt.unitlessAs().name().toLowerCase(Locale.ROOT));
            return DxfUnits.UNITLESS;
        }
        return u.get();
    }

    private void header(int from, int to) {
        for (int i = from; i + 1 < to; i++) {
            if (tags.code(i) == 9) {
                String var = tags.value(i);
                if (var.equals("$INSUNITS") && tags.code(i + 1) == 70) {
                    insUnits = parseIntOrNull(tags.value(i + 1));
                } else if (var.equals("$MEASUREMENT") && tags.code(i + 1) == 70) {
                    measurement = parseIntOrNull(tags.value(i + 1));
                }
            }
        }
    }

    private static Integer parseIntOrNull(String s) {
        try {
            return Integer.parseInt(s.trim());
        } catch (NumberFormatException e) {
            return null;
        }
    }

    private void tables(int from, int to) {
        for (int i = from; i < to; i++) {
            if (tags.code(i) == 0 && tags.valueIs(i, "LAYER")) {
                String name = null;
                int flags = 0;
                int color = 7;
                int j = i + 1;
                for (; j < to && tags.code(j) != 0; j++) {
                    switch (tags.code(j)) {
                        case 2 -> name = tags.value(j);
                        case 70 -> flags = intOr(tags.value(j), 0);
                        case 62 -> color = intOr(tags.value(j), 7);
                        default -> {}
                    }
                }
                if (name != null && ((flags & 1) != 0 || color < 0)) {
                    hiddenLayers.add(name);
                }
                i = j - 1;
            }
        }
    }

    private static int intOr(String s, int dflt) {
        Integer v = parseIntOrNull(s);
        return v == null ? dflt : v;
    }

    private void blocks(int from, int to) throws DxfException {
        int i = from;
        while (i < to) {
            if (tags.code(i) == 0 && tags.valueIs(i, "BLOCK")) {
                String name = "";
                double bx = 0;
                double by = 0;
                int j = i + 1;
                for (; j < to && tags.code(j) != 0; j++) {
                    switch (tags.code(j)) {
                        case 2 -> name = tags.value(j);
                        case 10 -> bx = blockNumber(j, name);
                        case 20 -> by = blockNumber(j, name);
                        default -> {}
                    }
                }
                int end = j;
                while (end < to && !(tags.code(end) == 0 && tags.valueIs(end, "ENDBLK"))) {
                    end++;
                }
                blocks.put(name, new Block(name, new Vec2(bx, by), entityList(j, end)));
                i = end + 1;
            } else {
                i++;
            }
        }
    }

    /** A block's base point coordinate; a value that is not a number refuses the drawing. */
    private double blockNumber(int i, String block) throws DxfException {
        try {
            return number(i);
        } catch (BadEntity ex) {
            String where = tags.binary ? tags.where(i) + ": " : "";
            throw new DxfException(
                    tags.source,
                    tags.binary ? 0 : tags.line(i) + 1,
                    where + "BLOCK '" + block + "': " + ex.getMessage());
        }
    }

    /** The entities in [from, to), with POLYLINE vertices attached to their POLYLINE. */
    private List<Entity> entityList(int from, int to) {
        List<Entity> out = new ArrayList<>();
        int i = from;
        while (i < to && tags.code(i) != 0) {
            i++;
        }
        Entity open = null;
        while (i < to) {
            String type = tags.value(i).toUpperCase(Locale.ROOT).intern();
            int j = i + 1;
            while (j < to && tags.code(j) != 0) {
                j++;
            }
            Entity e = new Entity(type, i, i + 1, j, type.equals("POLYLINE") ? new ArrayList<>() : List.of());
            if (type.equals("VERTEX") && open != null) {
                open.children.add(e);
            } else if (type.equals("SEQEND")) {
                open = null;
            } else if (type.equals("ATTRIB") && open == null) {
                count("ATTRIB", e);
            } else {
                open = type.equals("POLYLINE") ? e : null;
                out.add(e);
            }
            i = j;
        }
        return out;
    }

    private void count(String type, Entity e) {
        if (ignored.merge(type, 1, Integer::sum) == 1) {
            firstIgnored.put(type, e);
        }
    }

    /** One warning per kind of entity left out, with how many and where the first one is. */
    private void ignoredWarnings() {
        ignored.forEach((kind, n) -> {
            Entity e = firstIgnored.get(kind);
            String what = kind.equals("paper space") || kind.equals("on frozen or off layers")
                    ? n + (n == 1 ? " entity " : " entities ") + kind
                    : n + " " + kind + (n == 1 ? " entity" : " entities");
            String why = switch (kind) {
                case "paper space" -> "the sheet is cut from model space";
                case "on frozen or off layers" -> "their layers are hidden";
                case "POLYLINE mesh" -> "a 3D mesh has no outline to cut";
                default -> "not a line, arc or curve to cut";
            };
            warnings.add(what + " left out (" + why + "), the first: " + describe(e));
        });
    }

    // ---------------------------------------------------------------- entity access

    private String str(Entity e, int code, String dflt) {
        for (int i = e.first; i < e.end; i++) {
            if (tags.code(i) == code) {
                return tags.value(i);
            }
        }
        return dflt;
    }

    private double num(Entity e, int code, double dflt) throws BadEntity {
        for (int i = e.first; i < e.end; i++) {
            if (tags.code(i) == code) {
                return number(i);
            }
        }
        return dflt;
    }

    /** The value of tag i as a finite number; anything else is bad input at that tag. */
    private double number(int i) throws BadEntity {
        String v = tags.value(i);
        double d;
        try {
            d = Double.parseDouble(v);
        } catch (NumberFormatException ex) {
            d = Double.NaN;
        }
        if (!Double.isFinite(d)) {
            String shown = v.length() > 40 ? v.substring(0, 40) + "..." : v;
            throw new BadEntity(
                    "group " + tags.code(i) + " is '" + shown + "': expected " + meaning(tags.code(i))
                            + " (a finite number)",
                    i);
        }
        return d;
    }

    /** What a numeric group code holds, for messages. */
    static String meaning(int code) {
        if (code >= 10 && code <= 18) {
            return "an x coordinate";
        } else if (code >= 20 && code <= 28) {
            return "a y coordinate";
        } else if (code >= 30 && code <= 38) {
            return "a z coordinate or elevation";
        } else if (code >= 50 && code <= 58) {
            return "an angle in degrees";
        } else if (code >= 60 && code <= 99) {
            return "an integer";
        } else if (code >= 210 && code <= 239) {
            return "a component of the extrusion direction";
        }
        return "a number";
    }

    private double req(Entity e, int code) throws BadEntity {
        for (int i = e.first; i < e.end; i++) {
            if (tags.code(i) == code) {
                return number(i);
            }
        }
        throw new BadEntity("group " + code + " (" + meaning(code) + ") is missing", e.index);
    }

    private List<Double> nums(Entity e, int code) throws BadEntity {
        List<Double> out = new ArrayList<>();
        for (int i = e.first; i < e.end; i++) {
            if (tags.code(i) == code) {
                out.add(number(i));
            }
        }
        return out;
    }

    private boolean hasSubclass(Entity e) {
        for (int i = e.first; i < e.end; i++) {
            if (tags.code(i) == 100) {
                return true;
            }
        }
        return false;
    }

    /**
     * An entity that cannot be converted; the message names what is wrong. With a tag, the file
     * itself is broken there (a coordinate that is not a number, or missing): the drawing is
     * refused, since leaving the entity out would cut the sheet without it.
     */
    private static final class BadEntity extends Exception {
        private static final long serialVersionUID = 1L;
        /** The tag at fault (the entity's own for a missing group), or -1 for an entity that is only unusable. */
        final int tag;

        BadEntity(String m) {
            this(m, -1);
        }

        BadEntity(String m, int tag) {
            super(m, null, false, false);
            this.tag = tag;
        }
    }

    /** The drawing refused at a broken tag, with the line of the value (ASCII) or its byte (binary). */
    private DxfException refused(Entity e, BadEntity ex) {
        String h = str(e, 5, null);
        String what = e.type
                + (h != null ? " " + h : "")
                + (ex.tag == e.index ? "" : " (from " + tags.whereValue(e.index) + ")");
        if (tags.binary) {
            return new DxfException(tags.source, 0, tags.where(ex.tag) + ": " + what + ": " + ex.getMessage());
        }
        return new DxfException(tags.source, tags.line(ex.tag) + 1, what + ": " + ex.getMessage());
    }

    private String describe(Entity e) {
        String h = str(e, 5, null);
        return e.type + (h != null ? " " + h : " (no handle)") + " at " + tags.whereValue(e.index);
    }

    // ---------------------------------------------------------------- conversion

    private void warn(String w) {
        if (warnings.size() < MAX_WARNINGS) {
            warnings.add(w);
        } else {
            warningsLeftOut++;
        }
    }

    private void convert(Entity e, DxfAffine t, String insertLayer, int depth, Deque<String> stack)
            throws DxfException {
        if (truncated) {
            return;
        }
        if (++visits > MAX_VISITS) {
            throw new DxfException(
                    tags.source,
                    0,
                    "the drawing's inserts expand to more than " + MAX_VISITS
                            + " entities (the limit of one drawing; reached at " + describe(e)
                            + "): refused rather than cut"
                            + " without the rest");
        }
        if (str(e, 67, "0").trim().equals("1")) {
            count("paper space", e);
            return;
        }
        String layer = str(e, 8, "0");
        if (insertLayer != null && layer.equals("0")) {
            layer = insertLayer;
        }
        if (hiddenLayers.contains(layer)) {
            count("on frozen or off layers", e);
            return;
        }
        List<Curve2> local = new ArrayList<>();
        try {
            switch (e.type) {
                case "LINE" -> {
                    Vec2 a = new Vec2(req(e, 10), req(e, 20));
                    Vec2 b = new Vec2(req(e, 11), req(e, 21));
                    emit(layer, t, new Segment2(a, b));
                }
                case "CIRCLE" -> {
                    double r = req(e, 40);
                    if (!(r > 0)) {
                        throw new BadEntity("radius " + r + " is not > 0; the circle is left out");
                    }
                    Vec2 c = new Vec2(req(e, 10), req(e, 20));
                    emitOcs(e, layer, t, Arc2.circle(c, r, true));
                }
                case "ARC" -> {
                    double r = req(e, 40);
                    if (!(r > 0)) {
                        throw new BadEntity("radius " + r + " is not > 0; the arc is left out");
                    }
                    Vec2 c = new Vec2(req(e, 10), req(e, 20));
                    double a0 = num(e, 50, 0);
                    double a1 = num(e, 51, 360);
                    double sweep = ((a1 - a0) % 360 + 360) % 360;
                    if (sweep == 0) {
                        sweep = 360;
                    }
                    Vec2 s = c.plus(unit(a0).times(r));
                    Arc2 arc = sweep == 360
                            ? new Arc2(c, s, s, true)
                            : new Arc2(c, s, c.plus(unit(a0 + sweep).times(r)), true);
                    emitOcs(e, layer, t, arc);
                }
                case "LWPOLYLINE" -> lwpolyline(e, layer, t);
                case "POLYLINE" -> polyline(e, layer, t);
                case "ELLIPSE" -> ellipse(e, layer, t);
                case "SPLINE" -> spline(e, layer, t);
                case "INSERT" -> insert(e, layer, t, depth, stack);
                default -> {
                    if (!QUIET.contains(e.type)) {
                        count(e.type, e);
                    }
                }
            }
        } catch (BadEntity ex) {
            if (ex.tag >= 0) {
                throw refused(e, ex);
            }
            warn(describe(e) + ": " + ex.getMessage());
        } catch (IllegalArgumentException ex) {
            warn(describe(e) + ": " + ex.getMessage() + "; left out");
        }
    }

    /** A number for a message: up to 6 decimals, no trailing zeros. */
    static String num(double v) {
        String s = String.format(Locale.ROOT, "%.6f", v);
        s = s.contains(".") ? s.replaceAll("0+$", "").replaceAll("\\.$", "") : s;
        return s.equals("-0") ? "0" : s;
    }

    private static Vec2 unit(double deg) {
        double m = ((deg % 360) + 360) % 360;
        if (m == 0) {
            return new Vec2(1, 0);
        } else if (m == 90) {
            return new Vec2(0, 1);
        } else if (m == 180) {
            return new Vec2(-1, 0);
        } else if (m == 270) {
            return new Vec2(0, -1);
        }
        double r = Math.toRadians(deg);
        return new Vec2(Math.cos(r), Math.sin(r));
    }

    /** The map from an entity's object coordinate system to world XY (arbitrary axis algorithm). */
    private DxfAffine ocs(Entity e, double elevation) throws BadEntity {
        double nx = num(e, 210, 0);
        double ny = num(e, 220, 0);
        double nz = num(e, 230, 1);
        double n = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (n == 0) {
            throw new BadEntity("extrusion direction is the zero vector");
        }
        nx /= n;
        ny /= n;
        nz /= n;
        if (nx == 0 && ny == 0) {
            return nz > 0 ? DxfAffine.IDENTITY : new DxfAffine(-1, 0, 0, 1, 0, 0);
        }
        double ax;
        double ay;
        double az;
        if (Math.abs(nx) < 1.0 / 64 && Math.abs(ny) < 1.0 / 64) { // Wy x N
            ax = nz;
            ay = 0;
            az = -nx;
        } else { // Wz x N
            ax = -ny;
            ay = nx;
            az = 0;
        }
        double an = Math.sqrt(ax * ax + ay * ay + az * az);
        ax /= an;
        ay /= an;
        az /= an;
        // Ay = N x Ax
        double bx = ny * az - nz * ay;
        double by = nz * ax - nx * az;
        if (Math.abs(nz) < 1 - 1e-9) {
            warn(describe(e) + ": not parallel to the XY plane (extrusion " + nx + ", " + ny + ", " + nz
                    + "); projected onto XY");
        }
        return new DxfAffine(ax, bx, ay, by, elevation * nx, elevation * ny);
    }

    private void emitOcs(Entity e, String layer, DxfAffine t, Curve2 c) throws BadEntity {
        DxfAffine o = ocs(e, num(e, 30, 0));
        emit(layer, o.isIdentity() ? t : t.times(o), c);
    }

    private void emit(String layer, DxfAffine t, Curve2 c) {
        if (curveCount >= opt.maxCurves()) {
            truncated = true; // refused in run(), once every entity is left
            return;
        }
        if (t.isSimilarity()) {
            add(layer, t.applySimilar(c));
            return;
        }
        if (c instanceof Segment2 s) {
            add(layer, t.apply(s));
            return;
        }
        Arc2 a = (Arc2) c;
        double r = a.radius();
        double a0 = a.startAngleRad();
        double sw = a.sweepRad();
        Vec2 ctr = a.center();
        List<Curve2> out = DxfArcFitter.fit(
                List.of(new DxfArcFitter.Piece(
                        u -> t.apply(ctr.plus(Vec2.ofAngle(a0 + sw * u).times(r))), 0, 1)),
                a.isFullCircle(),
                opt.curveToleranceMm());
        for (Curve2 piece : out) {
            add(layer, piece);
        }
    }

    private void add(String layer, Curve2 c) {
        Box2 b = c.bounds();
        if (!(Math.max(
                        Math.max(Math.abs(b.minX()), Math.abs(b.maxX())),
                        Math.max(Math.abs(b.minY()), Math.abs(b.maxY())))
                <= MAX_COORDINATE_MM)) {
            throw new IllegalArgumentException("coordinates beyond " + MAX_COORDINATE_MM + " mm");
        }
        layers.computeIfAbsent(layer, k -> new ArrayList<>()).add(c);
        curveCount++;
    }

    /** Consecutive pieces of one smooth curve as tangent-continuous biarcs within the curve tolerance. */
    private void emitPieces(String layer, List<DxfArcFitter.Piece> pieces, boolean closed) {
        if (truncated) {
            return;
        }
        for (Curve2 c : DxfArcFitter.fit(pieces, closed, opt.curveToleranceMm())) {
            emit(layer, DxfAffine.IDENTITY, c);
        }
    }

    /** A vertex with the bulge of the segment that leaves it. */
    private record Vertex(Vec2 p, double bulge) {}

    private void lwpolyline(Entity e, String layer, DxfAffine t) throws BadEntity {
        List<Vertex> vs = new ArrayList<>();
        double x = Double.NaN;
        double y = Double.NaN;
        double bulge = 0;
        for (int i = e.first; i < e.end; i++) {
            int code = tags.code(i);
            if (code == 10) {
                if (!Double.isNaN(x)) {
                    vs.add(vertex(e, vs.size(), x, y, bulge));
                }
                x = number(i);
                y = Double.NaN;
                bulge = 0;
            } else if (code == 20) {
                y = number(i);
            } else if (code == 42) {
                bulge = number(i);
            }
        }
        if (!Double.isNaN(x)) {
            vs.add(vertex(e, vs.size(), x, y, bulge));
        }
        boolean closed = (((int) num(e, 70, 0)) & 1) != 0;
        DxfAffine o = ocs(e, num(e, 38, 0));
        emitPolyline(vs, closed, layer, o.isIdentity() ? t : t.times(o));
    }

    private static Vertex vertex(Entity e, int k, double x, double y, double bulge) throws BadEntity {
        if (Double.isNaN(y)) {
            throw new BadEntity("vertex " + (k + 1) + " has no y coordinate (group 20)", e.index);
        }
        return new Vertex(new Vec2(x, y), bulge);
    }

    private void polyline(Entity e, String layer, DxfAffine t) throws BadEntity {
        int flags = (int) num(e, 70, 0);
        if ((flags & (16 | 64)) != 0) {
            count("POLYLINE mesh", e);
            return;
        }
        boolean threeD = (flags & 8) != 0;
        List<Vertex> vs = new ArrayList<>();
        for (Entity v : e.children) {
            int vf = (int) num(v, 70, 0);
            if ((vf & 16) != 0 || (vf & 128) != 0) {
                continue; // spline frame control points, polyface records
            }
            vs.add(new Vertex(new Vec2(req(v, 10), req(v, 20)), threeD ? 0 : num(v, 42, 0)));
        }
        DxfAffine o = threeD ? DxfAffine.IDENTITY : ocs(e, num(e, 30, 0));
        emitPolyline(vs, (flags & 1) != 0, layer, o.isIdentity() ? t : t.times(o));
    }

    private void emitPolyline(List<Vertex> vs, boolean closed, String layer, DxfAffine t) {
        int n = vs.size();
        if (closed && n > 1 && vs.get(n - 1).p.equals(vs.get(0).p)) {
            n--; // a closed polyline that also repeats its first point
        }
        int segs = closed ? n : n - 1;
        for (int i = 0; i < segs; i++) {
            Vertex a = vs.get(i);
            Vec2 b = vs.get((i + 1) % n).p;
            emit(layer, t, bulged(a.p, b, a.bulge));
        }
    }

    /** The segment or arc from a to b with the DXF bulge tan(sweep / 4) (negative: clockwise). */
    static Curve2 bulged(Vec2 a, Vec2 b, double bulge) {
        if (Math.abs(bulge) < 1e-12 || a.equals(b)) {
            return new Segment2(a, b);
        }
        Vec2 chord = b.minus(a);
        Vec2 mid = a.interpolate(b, 0.5);
        Vec2 c = mid.plus(chord.leftNormal().times((1 - bulge * bulge) / (4 * bulge)));
        return new Arc2(c, a, b, bulge > 0);
    }

    private void ellipse(Entity e, String layer, DxfAffine t) throws BadEntity {
        Vec2 c = new Vec2(req(e, 10), req(e, 20));
        Vec2 major = new Vec2(req(e, 11), req(e, 21));
        double ratio = req(e, 40);
        double u0 = num(e, 41, 0);
        double u1 = num(e, 42, 2 * Math.PI);
        double nz = num(e, 230, 1);
        if (major.norm() == 0 || !(ratio > 0)) {
            throw new BadEntity(String.format(
                    Locale.ROOT,
                    "major axis (%s, %s) and axis ratio %s do not describe an ellipse (the axis must not be zero, the"
                            + " ratio must be > 0)",
                    num(major.x()),
                    num(major.y()),
                    num(ratio)));
        }
        // the minor axis is N x major: turned -90 degrees for an extrusion of (0, 0, -1)
        Vec2 minor = (nz >= 0 ? major.leftNormal() : major.leftNormal().negated()).times(ratio);
        if (ratio > 1) {
            // QCAD writes the longer axis as the "minor" one: AutoCAD and ezdxf swap the axes, which
            // turns the parameter by a quarter (old u = new u + pi / 2), and read the same curve
            Vec2 longer = minor;
            minor = major.negated();
            major = longer;
            ratio = 1 / ratio;
            u0 -= Math.PI / 2;
            u1 -= Math.PI / 2;
        }
        double sweep = u1 - u0;
        if (sweep <= 0) {
            // one step instead of adding 2 pi until positive, which never ends for |u0| >> 2 pi
            sweep = sweep % (2 * Math.PI) + 2 * Math.PI;
        }
        if (sweep > 2 * Math.PI) {
            sweep = 2 * Math.PI;
        }
        double span = sweep;
        double start = u0;
        if (Math.abs(ratio - 1) <= 1e-12) { // a circle or circular arc
            double r = major.norm();
            Vec2 s = c.plus(major.times(Math.cos(start)).plus(minor.times(Math.sin(start))));
            Vec2 en = c.plus(major.times(Math.cos(start + span)).plus(minor.times(Math.sin(start + span))));
            boolean ccw = nz >= 0;
            Arc2 arc = Math.abs(span - 2 * Math.PI) < 1e-12 ? new Arc2(c, s, s, ccw) : new Arc2(c, s, en, ccw);
            if (Math.abs(c.distance(en) - r) <= 1e-9 * Math.max(1, r)) {
                emit(layer, t, arc);
                return;
            }
        }
        int pieces = Math.max(1, (int) Math.ceil(span / (Math.PI / 2)));
        boolean full = span == 2 * Math.PI;
        double last = start + span;
        Vec2 ax = major;
        Vec2 bx = minor;
        DoubleFunction<Vec2> f = u -> {
            double v = full && u == last ? start : u; // a closed ellipse ends exactly where it starts
            return t.apply(c.plus(ax.times(Math.cos(v)).plus(bx.times(Math.sin(v)))));
        };
        List<DxfArcFitter.Piece> ps = new ArrayList<>();
        for (int k = 0; k < pieces; k++) {
            double a = start + span * k / pieces;
            double b = k == pieces - 1 ? last : start + span * (k + 1) / pieces;
            ps.add(new DxfArcFitter.Piece(f, a, b));
        }
        emitPieces(layer, ps, full);
    }

    private void spline(Entity e, String layer, DxfAffine t) throws BadEntity {
        int degree = (int) num(e, 71, 3);
        List<Double> knots = nums(e, 40);
        List<Double> xs = nums(e, 10);
        List<Double> ys = nums(e, 20);
        List<Double> ws = nums(e, 41);
        if (!hasSubclass(e) && tags.binary == false && str(e, 5, null) == null) {
            warn(describe(e) + ": no handle and no AcDbSpline subclass marker; read by its group codes");
        }
        if (xs.size() != ys.size()) {
            throw new BadEntity(xs.size() + " x but " + ys.size() + " y control point coordinates");
        }
        if (xs.isEmpty()) {
            List<Double> fx = nums(e, 11);
            List<Double> fy = nums(e, 21);
            if (fx.size() < 2 || fx.size() != fy.size()) {
                throw new BadEntity("neither control points nor fit points");
            }
            List<Vec2> pts = new ArrayList<>();
            for (int i = 0; i < fx.size(); i++) {
                pts.add(new Vec2(fx.get(i), fy.get(i)));
            }
            fitPointSpline(pts, layer, t);
            return;
        }
        int n = xs.size();
        if (degree < 1 || degree > 25) {
            throw new BadEntity("degree " + degree + " is not between 1 and 25");
        }
        if (n < degree + 1) {
            throw new BadEntity(n + " control points are too few for degree " + degree);
        }
        if (knots.size() != n + degree + 1) {
            throw new BadEntity(knots.size() + " knots, but " + n + " control points of degree " + degree + " need "
                    + (n + degree + 1));
        }
        for (int i = 1; i < knots.size(); i++) {
            if (knots.get(i) < knots.get(i - 1)) {
                throw new BadEntity("knots decrease at knot " + (i + 1));
            }
        }
        if (!ws.isEmpty() && ws.size() != n) {
            throw new BadEntity(ws.size() + " weights for " + n + " control points");
        }
        double[] u = knots.stream().mapToDouble(Double::doubleValue).toArray();
        double[] px = xs.stream().mapToDouble(Double::doubleValue).toArray();
        double[] py = ys.stream().mapToDouble(Double::doubleValue).toArray();
        double[] w = ws.isEmpty()
                ? null
                : ws.stream().mapToDouble(Double::doubleValue).toArray();
        if (w != null) {
            for (double wi : w) {
                if (!(wi > 0)) {
                    throw new BadEntity("weight " + wi + " is not > 0");
                }
            }
        }
        final int p = degree;
        List<DxfArcFitter.Piece> ps = new ArrayList<>();
        for (int k = p; k < n; k++) {
            if (u[k + 1] > u[k]) {
                final int span = k;
                ps.add(new DxfArcFitter.Piece(s -> t.apply(deBoor(span, s, p, u, px, py, w)), u[k], u[k + 1]));
            }
        }
        emitPieces(layer, ps, ps.size() > 0 && closedCurve(ps));
    }

    /** The NURBS point at parameter s in knot span k (u[k] <= s <= u[k + 1]). */
    static Vec2 deBoor(int k, double s, int p, double[] u, double[] px, double[] py, double[] w) {
        double[] dx = new double[p + 1];
        double[] dy = new double[p + 1];
        double[] dw = new double[p + 1];
        for (int j = 0; j <= p; j++) {
            int i = j + k - p;
            double wi = w == null ? 1 : w[i];
            dx[j] = px[i] * wi;
            dy[j] = py[i] * wi;
            dw[j] = wi;
        }
        for (int r = 1; r <= p; r++) {
            for (int j = p; j >= r; j--) {
                int i = j + k - p;
                double den = u[i + p - r + 1] - u[i];
                double alpha = den == 0 ? 0 : (s - u[i]) / den;
                dx[j] = (1 - alpha) * dx[j - 1] + alpha * dx[j];
                dy[j] = (1 - alpha) * dy[j - 1] + alpha * dy[j];
                dw[j] = (1 - alpha) * dw[j - 1] + alpha * dw[j];
            }
        }
        return new Vec2(dx[p] / dw[p], dy[p] / dw[p]);
    }

    /** True when the last piece ends where the first starts (within 1e-9 of the curve's size). */
    private static boolean closedCurve(List<DxfArcFitter.Piece> ps) {
        DxfArcFitter.Piece first = ps.get(0);
        DxfArcFitter.Piece last = ps.get(ps.size() - 1);
        Vec2 a = first.f().apply(first.u0());
        Vec2 b = last.f().apply(last.u1());
        return a.distance(b) <= 1e-9 * Math.max(1, Math.max(a.norm(), b.norm()));
    }

    /** A curve through fit points only: a Catmull-Rom spline through them, then arcs. */
    private void fitPointSpline(List<Vec2> pts, String layer, DxfAffine t) {
        int n = pts.size();
        List<DxfArcFitter.Piece> ps = new ArrayList<>();
        for (int i = 0; i + 1 < n; i++) {
            Vec2 p0 = pts.get(Math.max(0, i - 1));
            Vec2 p1 = pts.get(i);
            Vec2 p2 = pts.get(i + 1);
            Vec2 p3 = pts.get(Math.min(n - 1, i + 2));
            if (p1.equals(p2)) {
                continue;
            }
            ps.add(new DxfArcFitter.Piece(
                    s -> {
                        double s2 = s * s;
                        double s3 = s2 * s;
                        double x = 0.5
                                * (2 * p1.x()
                                        + (-p0.x() + p2.x()) * s
                                        + (2 * p0.x() - 5 * p1.x() + 4 * p2.x() - p3.x()) * s2
                                        + (-p0.x() + 3 * p1.x() - 3 * p2.x() + p3.x()) * s3);
                        double y = 0.5
                                * (2 * p1.y()
                                        + (-p0.y() + p2.y()) * s
                                        + (2 * p0.y() - 5 * p1.y() + 4 * p2.y() - p3.y()) * s2
                                        + (-p0.y() + 3 * p1.y() - 3 * p2.y() + p3.y()) * s3);
                        return t.apply(new Vec2(x, y));
                    },
                    0,
                    1));
        }
        if (!ps.isEmpty()) {
            emitPieces(layer, ps, false);
        }
    }

    /**
     * The cycle of blocks an insert closes, named in insertion order: "block 'A' inserts itself"
     * or "blocks insert each other in a cycle: A -> B -> A".
     *
     * @param stack the blocks being expanded, the innermost first
     */
    static String cycle(Deque<String> stack, String name) {
        List<String> path = new ArrayList<>(stack);
        java.util.Collections.reverse(path);
        List<String> loop = new ArrayList<>(path.subList(path.indexOf(name), path.size()));
        if (loop.size() == 1) {
            return "block '" + name + "' inserts itself";
        }
        loop.add(name);
        return "blocks insert each other in a cycle: " + String.join(" -> ", loop);
    }

    private void insert(Entity e, String layer, DxfAffine t, int depth, Deque<String> stack)
            throws BadEntity, DxfException {
        String name = str(e, 2, "");
        Block b = blocks.get(name);
        if (b == null) {
            throw new BadEntity("block '" + name + "' is not defined");
        }
        if (stack.contains(name)) {
            if (reportedCycles.add(name)) {
                warn(describe(e) + ": " + cycle(stack, name) + "; the inner insert is left out");
            }
            return;
        }
        if (depth >= opt.maxInsertDepth()) {
            warn(describe(e) + ": blocks nested deeper than " + opt.maxInsertDepth() + "; left out");
            return;
        }
        double sx = num(e, 41, 1);
        double sy = num(e, 42, 1);
        double rot = num(e, 50, 0);
        int cols = Math.max(1, (int) num(e, 70, 1));
        int rows = Math.max(1, (int) num(e, 71, 1));
        double dx = num(e, 44, 0);
        double dy = num(e, 45, 0);
        if (sx == 0 || sy == 0) {
            throw new BadEntity("scale " + sx + " x " + sy + " flattens the block");
        }
        if ((long) cols * rows > 10_000) {
            warn(describe(e) + ": an array of " + cols + " x " + rows + " inserts is cut to the first 10000");
        }
        DxfAffine o = ocs(e, 0);
        Vec2 at = new Vec2(req(e, 10), req(e, 20));
        DxfAffine r = DxfAffine.rotationDeg(rot);
        stack.push(name);
        try {
            int done = 0;
            for (int row = 0; row < rows && done < 10_000; row++) {
                for (int col = 0; col < cols && done < 10_000; col++, done++) {
                    Vec2 cell = r.apply(new Vec2(col * dx, row * dy));
                    DxfAffine local = DxfAffine.translation(at.x() + cell.x(), at.y() + cell.y())
                            .times(r)
                            .times(DxfAffine.scale(sx, sy))
                            .times(DxfAffine.translation(-b.base.x(), -b.base.y()));
                    DxfAffine whole = t.times(o).times(local);
                    for (Entity child : b.entities) {
                        convert(child, whole, layer, depth + 1, stack);
                    }
                }
            }
        } finally {
            stack.pop();
        }
    }
}
