package org.fresa.stepnc;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalInt;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Function;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.stepnc.Iso14649Schema.EntityDef;
import org.fresa.stepnc.StepNcProgram.Dialect;

/**
 * Turns a {@link StepFile} into the ISO 14649 model. Attribute positions come from
 * {@link Iso14649Schema}; this class only says which attribute feeds which model field.
 * Unknown entities are counted, never fatal; an attribute of the wrong kind where the model needs
 * it is a {@link StepParseException} at the instance's line.
 */
final class Iso14649Binder {

    /** Real files nest workplans a few levels; deeper chains are refused before they exhaust the stack. */
    static final int MAX_WORKPLAN_NESTING = 100;
    /** Points further than this (mm) are refused: their squares and products would overflow. */
    static final double MAX_COORDINATE_MM = 1e9;

    private static final org.fresa.geom.Tolerance SAME_FRAME = org.fresa.geom.Tolerance.DEFAULT;

    private final StepFile file;
    private final Iso14649Schema schema = Iso14649Schema.get();
    private final Dialect dialect;
    private final Set<String> spellings = new LinkedHashSet<>();
    private final List<String> warnings = new ArrayList<>();
    private final Map<Long, Feature> features = new HashMap<>();
    private final Map<Long, Tool> tools = new HashMap<>();
    private final Map<Long, Setup> setups = new HashMap<>();
    private final Map<Long, MachiningWorkingstep> workingsteps = new HashMap<>();

    Iso14649Binder(StepFile file) {
        this.file = file;
        this.dialect = detectDialect(file);
    }

    static Dialect detectDialect(StepFile file) {
        String pre = file.headerText("FILE_NAME", 4).orElse("").toUpperCase(Locale.ROOT);
        if (file.schemas().contains("COMBINED_SCHEMA") || pre.contains("ST-GENERATOR")) {
            return Dialect.STEP_MODELER;
        }
        // ISO writes the spindle in rev/s; a value above 300 (18000 rpm) can only be rpm, which
        // is what GRIMA's JSDAI-based writers put there even under MACHINING_SCHEMA
        for (int k = 0; k < file.size(); k++) {
            if (file.firstTypeAt(k).equals("MILLING_TECHNOLOGY")) {
                StepValue s = file.instanceAt(k).record().param(3);
                double v = s instanceof StepValue.Real r ? r.value() : s instanceof StepValue.Int i ? i.value() : 0;
                if (Math.abs(v) > 300) {
                    return Dialect.STEP_MODELER;
                }
            }
        }
        return Dialect.ISO_14649;
    }

    /** A view of one instance through its schema entity. */
    private final class E {
        final StepInstance inst;
        final StepRecord rec;
        final EntityDef def;

        E(StepInstance inst, StepRecord rec, EntityDef def) {
            this.inst = inst;
            this.rec = rec;
            this.def = def;
        }

        boolean has(String attr) {
            return def.indexOf(attr) >= 0;
        }

        StepValue v(String attr) {
            int i = def.indexOf(attr);
            return i < 0 ? StepValue.UNSET : rec.param(i);
        }

        String name() {
            return def.name();
        }

        long id() {
            return inst.id();
        }
    }

    private StepParseException error(E e, String problem) {
        return new StepParseException(file.source(), e.inst.line(), e.inst.column(), e.inst.id(), problem);
    }

    // the answers of known() by instance index, direct-mapped: the binding asks for most instances
    // several times (points, placements, tools), and the bound on the size keeps a large file's
    // heap as it was (the store's own cache of decoded instances is bounded the same way). One of
    // the reader's fast paths (docs/performance.md): with the keyword table and the store's pages
    // it took a read of example 2 from 1.16-1.48 ms to 0.93-1.24 ms of thread CPU
    private static final int KNOWN_CACHE = 2048;
    private final int[] knownIndex = new int[KNOWN_CACHE];

    @SuppressWarnings("unchecked")
    private final Optional<E>[] knownAnswer = (Optional<E>[]) new Optional<?>[KNOWN_CACHE];

    /** The instance as a known, simple entity; empty when it is unknown or complex. */
    private Optional<E> known(long id) {
        int i = file.indexOf(id);
        if (i < 0) {
            return Optional.empty();
        }
        int slot = i & (KNOWN_CACHE - 1);
        Optional<E> answer = knownAnswer[slot];
        if (answer != null && knownIndex[slot] == i) {
            return answer;
        }
        answer = lookUp(file.instanceAt(i));
        knownAnswer[slot] = answer;
        knownIndex[slot] = i;
        return answer;
    }

    private Optional<E> lookUp(StepInstance inst) {
        if (inst.isComplex()) {
            return Optional.empty();
        }
        Optional<Iso14649Schema.Lookup> found = find(inst.record().type());
        if (found.isEmpty()) {
            return Optional.empty();
        }
        Iso14649Schema.Lookup l = found.get();
        // noted once per instance: spellings is a set, so asking again would add nothing
        if (l.isAlias()) {
            spellings.add(l.spelling() + " read as " + l.def().name());
        }
        int n = inst.record().params().size();
        int want = l.def().attributes().size();
        if (n != want) {
            spellings.add(l.spelling() + " written with " + n + " attributes (the schema subset lists " + want
                    + (n < want ? "; the missing ones read as unset)" : "; the extra ones are ignored)"));
        }
        return Optional.of(new E(inst, inst.record(), l.def()));
    }

    // the schema's answers by the file's own type names: the store pools each name once, so this
    // map finds them on identity, where the schema's shared map compares their characters
    private final Map<String, Optional<Iso14649Schema.Lookup>> lookups = new HashMap<>();

    private Optional<Iso14649Schema.Lookup> find(String type) {
        Optional<Iso14649Schema.Lookup> l = lookups.get(type);
        if (l == null) {
            l = schema.find(type);
            // bounded as the schema's own map is: a file of made-up names must not grow it forever
            if (lookups.size() < 10_000) {
                lookups.put(type, l);
            }
        }
        return l;
    }

    private String typeOf(long id) {
        int i = file.indexOf(id);
        return i < 0 ? "?" : file.instanceAt(i).type();
    }

    // ---- attribute accessors ----

    /**
     * An optional attribute of one kind of value: empty when it is left without a value, else an
     * error saying what it should be.
     */
    private <V extends StepValue, T> Optional<T> optional(
            E e, String attr, Class<V> kind, Function<V, T> value, String expected) throws StepParseException {
        StepValue v = e.v(attr);
        if (kind.isInstance(v)) {
            return Optional.of(value.apply(kind.cast(v)));
        }
        if (v.absent()) {
            return Optional.empty();
        }
        throw error(e, e.name() + "." + attr + " should be " + expected + ", found " + v);
    }

    private Optional<Long> refId(E e, String attr) throws StepParseException {
        return optional(e, attr, StepValue.Ref.class, StepValue.Ref::id, "a reference (#n)");
    }

    /** A reference to a known entity that is one of the given supertypes. */
    private Optional<E> ref(E e, String attr, String... kinds) throws StepParseException {
        Optional<Long> id = refId(e, attr);
        if (id.isEmpty()) {
            return Optional.empty();
        }
        Optional<E> t = known(id.get());
        if (t.isEmpty()) {
            return Optional.empty();
        }
        for (String k : kinds) {
            if (t.get().def.isA(k)) {
                return t;
            }
        }
        throw error(
                e,
                e.name() + "." + attr + " should be "
                        + String.join(" or ", kinds).toLowerCase(Locale.ROOT) + ", found #" + id.get() + " "
                        + typeOf(id.get()));
    }

    private List<Long> refList(E e, String attr) throws StepParseException {
        StepValue v = e.v(attr);
        List<Long> out = new ArrayList<>();
        if (v instanceof StepValue.Aggregate a) {
            for (StepValue item : a.items()) {
                if (item instanceof StepValue.Ref r) {
                    out.add(r.id());
                } else if (!(item instanceof StepValue.Unset)) {
                    throw error(e, e.name() + "." + attr + " should list references, found " + item);
                }
            }
        } else if (v instanceof StepValue.Ref r) {
            out.add(r.id());
        } else if (!(v instanceof StepValue.Unset)) {
            throw error(e, e.name() + "." + attr + " should be a list, found " + v);
        }
        return out;
    }

    private String text(E e, String attr) throws StepParseException {
        return optional(e, attr, StepValue.Text.class, StepValue.Text::value, "a string")
                .orElse("");
    }

    private OptionalDouble num(E e, String attr) throws StepParseException {
        return number(e, attr, e.v(attr), 0);
    }

    private OptionalDouble number(E e, String attr, StepValue v, int depth) throws StepParseException {
        if (v instanceof StepValue.Real r) {
            return OptionalDouble.of(r.value());
        }
        if (v instanceof StepValue.Int i) {
            return OptionalDouble.of(i.value());
        }
        if (v.absent()) {
            return OptionalDouble.empty();
        }
        if (v instanceof StepValue.Typed t && depth < 8) {
            return number(e, attr, t.value(), depth + 1);
        }
        if (v instanceof StepValue.Ref r && depth < 8) {
            Optional<E> t = known(r.id());
            if (t.isPresent()) {
                E m = t.get();
                if (m.def.isA("TOLERANCED_LENGTH_MEASURE")) {
                    return number(m, "theoretical_size", m.v("theoretical_size"), depth + 1);
                }
                if (m.def.isA("NUMERIC_PARAMETER")) {
                    return number(m, "its_parameter_value", m.v("its_parameter_value"), depth + 1);
                }
            }
            throw error(e, e.name() + "." + attr + " should be a number, found #" + r.id() + " " + typeOf(r.id()));
        }
        throw error(e, e.name() + "." + attr + " should be a number, found " + v);
    }

    private double required(E e, String attr) throws StepParseException {
        OptionalDouble d = num(e, attr);
        if (d.isEmpty()) {
            throw error(e, e.name() + "." + attr + " has no value");
        }
        return d.getAsDouble();
    }

    private OptionalInt integer(E e, String attr) throws StepParseException {
        StepValue v = e.v(attr);
        if (v instanceof StepValue.Int i && i.value() >= Integer.MIN_VALUE && i.value() <= Integer.MAX_VALUE) {
            return OptionalInt.of((int) i.value());
        }
        if (v instanceof StepValue.Real r && r.value() == Math.rint(r.value()) && Math.abs(r.value()) < 1e9) {
            return OptionalInt.of((int) r.value());
        }
        if (v.absent()) {
            return OptionalInt.empty();
        }
        throw error(e, e.name() + "." + attr + " should be an integer, found " + v);
    }

    private Optional<String> enumeration(E e, String attr) throws StepParseException {
        return optional(e, attr, StepValue.Enumeration.class, StepValue.Enumeration::name, "an enumeration (.X.)");
    }

    private Optional<Boolean> bool(E e, String attr) throws StepParseException {
        Optional<String> s = enumeration(e, attr);
        if (s.isEmpty()) {
            return Optional.empty();
        }
        return switch (s.get()) {
            case "T", "TRUE" -> Optional.of(true);
            case "F", "FALSE" -> Optional.of(false);
            default -> Optional.empty();
        };
    }

    /** Checks that a referenced entity is of the supertype its attribute asks for. */
    private void expectKind(E owner, E target, String supertype, String should) throws StepParseException {
        if (!target.def.isA(supertype)) {
            throw error(owner, should + ", found #" + target.id() + " " + target.name());
        }
    }

    /** The kind an entity is named as, or the catch-all for an entity Fresa does not model. */
    private static <T extends Enum<T>> T kindOf(Class<T> kinds, String entity, T other) {
        try {
            return Enum.valueOf(kinds, entity);
        } catch (IllegalArgumentException ex) {
            return other;
        }
    }

    /**
     * A strategy that sets none of the milling parameters (overlap, passes, directions, cut mode):
     * a drilling strategy with its own, or one Fresa does not model.
     */
    static Strategy withoutMillingParameters(
            long id, Strategy.StrategyType type, String entity, Optional<DrillingStrategy> drilling) {
        return new Strategy(
                id,
                type,
                entity,
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                drilling);
    }

    // ---- geometry ----

    private Vec3 point(E p) throws StepParseException {
        double[] c = coordinatesOf(p, "CARTESIAN_POINT", "coordinates", 1, "a point has 1 to 3 coordinates");
        for (double x : c) {
            if (!(Math.abs(x) <= MAX_COORDINATE_MM)) {
                throw error(
                        p,
                        "coordinate " + x + " is out of range (at most " + MAX_COORDINATE_MM + " mm from the origin)");
            }
        }
        return new Vec3(c[0], c.length > 1 ? c[1] : 0, c.length > 2 ? c[2] : 0);
    }

    private Vec3 direction(E d) throws StepParseException {
        double[] c = coordinatesOf(d, "DIRECTION", "direction_ratios", 2, "a direction has 2 or 3 ratios");
        Vec3 v = new Vec3(c[0], c[1], c.length > 2 ? c[2] : 0);
        if (v.norm() == 0 || !Double.isFinite(v.norm())) {
            throw error(
                    d,
                    "the direction (" + v.x() + ", " + v.y() + ", " + v.z() + ") has no usable length"
                            + " (zero, too small or too large to normalise)");
        }
        return v.normalized();
    }

    /**
     * The numbers of a point's or a direction's list, from {@code fewest} to 3 of them.
     *
     * @param count how the message says the count allowed
     */
    private double[] coordinatesOf(E e, String kind, String attr, int fewest, String count) throws StepParseException {
        if (!e.def.isA(kind)) {
            throw error(e, "expected a " + kind + ", found " + e.name());
        }
        double[] c = coordinates(e, attr);
        if (c.length < fewest || c.length > 3) {
            throw error(e, count + ", found " + c.length);
        }
        return c;
    }

    private double[] coordinates(E e, String attr) throws StepParseException {
        StepValue v = e.v(attr);
        if (!(v instanceof StepValue.Aggregate a)) {
            throw error(e, e.name() + "." + attr + " should be a list of numbers, found " + v);
        }
        double[] out = new double[a.items().size()];
        for (int i = 0; i < out.length; i++) {
            OptionalDouble d = number(e, attr, a.items().get(i), 0);
            if (d.isEmpty()) {
                throw error(e, e.name() + "." + attr + " has an unset coordinate");
            }
            out[i] = d.getAsDouble();
        }
        return out;
    }

    private Optional<Vec3> pointAttr(E e, String attr) throws StepParseException {
        Optional<E> p = ref(e, attr, "CARTESIAN_POINT");
        return p.isPresent() ? Optional.of(point(p.get())) : Optional.empty();
    }

    private Optional<Vec3> directionAttr(E e, String attr) throws StepParseException {
        Optional<E> p = ref(e, attr, "DIRECTION");
        return p.isPresent() ? Optional.of(direction(p.get())) : Optional.empty();
    }

    /** AXIS2_PLACEMENT_3D as a frame; unset axis is +z, unset reference direction is +x. */
    private Transform3 placement(E a) throws StepParseException {
        Vec3 origin = pointAttr(a, "location").orElse(Vec3.ZERO);
        Vec3 z = directionAttr(a, "axis").orElse(Vec3.UNIT_Z);
        Optional<Vec3> ref = directionAttr(a, "ref_direction");
        Vec3 x = ref.orElse(Math.abs(z.x()) > 0.9 ? Vec3.UNIT_Y : Vec3.UNIT_X);
        try {
            return Transform3.ofFrame(origin, z, x);
        } catch (IllegalArgumentException ex) {
            // ISO 10303-42 build_axes would reject it; GRIMA's files have such placements, so
            // the default reference direction is used and the file is told about
            warnings.add("#" + a.id()
                    + " AXIS2_PLACEMENT_3D: ref_direction parallel to the axis; the default x direction is used");
            return Transform3.ofFrame(origin, z, Math.abs(z.x()) > 0.9 ? Vec3.UNIT_Y : Vec3.UNIT_X);
        }
    }

    private Optional<Transform3> placementAttr(E e, String attr) throws StepParseException {
        Optional<E> p = ref(e, attr, "AXIS2_PLACEMENT_3D");
        return p.isPresent() ? Optional.of(placement(p.get())) : Optional.empty();
    }

    /** PLANE or ELEMENTARY_SURFACE: its position. */
    private Optional<Transform3> planeAttr(E e, String attr) throws StepParseException {
        Optional<E> p = ref(e, attr, "PLANE");
        return p.isPresent() ? placementAttr(p.get(), "position") : Optional.empty();
    }

    // ---- the geometry binding, shared with the AP238 AIM binder ----

    private E geometry(long id, String kind) throws StepParseException {
        Optional<E> e = known(id);
        if (e.isEmpty() || !e.get().def.isA(kind)) {
            int i = file.indexOf(id);
            StepInstance inst = i < 0 ? null : file.instanceAt(i);
            throw new StepParseException(
                    file.source(),
                    inst == null ? 0 : inst.line(),
                    inst == null ? 0 : inst.column(),
                    id,
                    "expected a " + kind + ", found #" + id + " " + typeOf(id));
        }
        return e.get();
    }

    /** CARTESIAN_POINT #id, in the file's length unit. */
    Vec3 pointOf(long id) throws StepParseException {
        return point(geometry(id, "CARTESIAN_POINT"));
    }

    /** DIRECTION #id, normalised. */
    Vec3 directionOf(long id) throws StepParseException {
        return direction(geometry(id, "DIRECTION"));
    }

    /** AXIS2_PLACEMENT_3D #id as a frame, in the file's length unit. */
    Transform3 placementOf(long id) throws StepParseException {
        return placement(geometry(id, "AXIS2_PLACEMENT_3D"));
    }

    /** PLANE #id: its position. */
    Optional<Transform3> planeOf(long id) throws StepParseException {
        return placementAttr(geometry(id, "PLANE"), "position");
    }

    /** The doubts the geometry binding noted so far. */
    List<String> geometryWarnings() {
        return List.copyOf(warnings);
    }

    // ---- project level ----

    StepNcProgram bind() throws StepParseException {
        Map<String, Integer> unknown = new TreeMap<>();
        Set<Long> referencedByWorkplan = new HashSet<>();
        List<Long> allWorkplans = new ArrayList<>();
        List<Long> allWorkingsteps = new ArrayList<>();
        List<Long> projects = new ArrayList<>();
        for (int i = 0; i < file.size(); i++) {
            boolean complex = file.isComplexAt(i);
            Optional<Iso14649Schema.Lookup> l = complex ? Optional.empty() : find(file.firstTypeAt(i));
            if (l.isEmpty()) {
                unknown.merge(complex ? file.instanceAt(i).type() : file.firstTypeAt(i), 1, Integer::sum);
                continue;
            }
            long instId = file.idAt(i);
            switch (l.get().def().name()) {
                case "PROJECT" -> projects.add(instId);
                case "WORKPLAN" -> {
                    allWorkplans.add(instId);
                    E w = known(instId).orElseThrow();
                    referencedByWorkplan.addAll(refList(w, "its_elements"));
                }
                case "MACHINING_WORKINGSTEP" -> allWorkingsteps.add(instId);
                default -> {}
            }
        }
        String projectId = "";
        Optional<Workplan> main = Optional.empty();
        List<Workpiece> workpieces = new ArrayList<>();
        Long mainId = null;
        if (!projects.isEmpty()) {
            E p = known(projects.get(0)).orElseThrow();
            if (projects.size() > 1) {
                warnings.add("the file has " + projects.size() + " PROJECT instances; #" + p.id() + " is used");
            }
            projectId = text(p, "its_id");
            Optional<E> mw = ref(p, "main_workplan", "WORKPLAN");
            if (mw.isPresent()) {
                mainId = mw.get().id();
            }
            for (long wp : refList(p, "its_workpieces")) {
                Optional<E> w = known(wp);
                if (w.isPresent() && w.get().def.isA("WORKPIECE")) {
                    workpieces.add(workpiece(w.get()));
                }
            }
        } else {
            warnings.add("the file has no PROJECT; the first workplan not inside another one is executed");
        }
        if (mainId == null) {
            for (long w : allWorkplans) {
                if (!referencedByWorkplan.contains(w)) {
                    mainId = w;
                    break;
                }
            }
        }
        if (mainId != null) {
            main = Optional.of(workplan(known(mainId).orElseThrow(), new ArrayDeque<>(), Optional.empty()));
        } else {
            warnings.add("no workplan to execute");
        }
        List<MachiningWorkingstep> executed = main.map(Workplan::flatten).orElse(List.of());
        Set<Long> executedIds = new HashSet<>();
        executed.forEach(w -> executedIds.add(w.instanceId()));
        List<StepNcProgram.Skipped> skipped = new ArrayList<>();
        for (long wsId : allWorkingsteps) {
            if (executedIds.contains(wsId)) {
                continue;
            }
            String reason = referencedByWorkplan.contains(wsId)
                    ? "in a workplan that the main workplan does not run"
                    : "not referenced by any workplan";
            E ws = known(wsId).orElseThrow();
            String id = ws.v("its_id") instanceof StepValue.Text t ? t.value() : "";
            Optional<MachiningWorkingstep> bound;
            try {
                bound = Optional.of(workingstep(ws, Optional.empty()));
            } catch (StepParseException ex) {
                bound = Optional.empty();
                reason = reason + "; it cannot be bound either: " + ex.problem();
            }
            skipped.add(new StepNcProgram.Skipped(wsId, id, reason, bound));
        }
        return new StepNcProgram(
                file.source(),
                file.schemas(),
                dialect,
                file.size(),
                projectId,
                main,
                workpieces,
                executed,
                skipped,
                unknown,
                new ArrayList<>(spellings),
                warnings,
                file);
    }

    private Workpiece workpiece(E w) throws StepParseException {
        Optional<String> material = Optional.empty();
        Optional<E> m = ref(w, "its_material", "MATERIAL");
        if (m.isPresent()) {
            material = Optional.of(text(m.get(), "material_identifier"));
        }
        Optional<Workpiece.Block> block = Optional.empty();
        Optional<Long> bg = refId(w, "its_bounding_geometry");
        if (bg.isPresent()) {
            Optional<E> b = known(bg.get());
            if (b.isPresent() && b.get().def.isA("BLOCK")) {
                E blk = b.get();
                double x = required(blk, "x");
                double y = required(blk, "y");
                double z = required(blk, "z");
                if (x > 0 && y > 0 && z > 0) {
                    block = Optional.of(
                            new Workpiece.Block(placementAttr(blk, "position").orElse(Transform3.IDENTITY), x, y, z));
                } else {
                    // ISO 10303-42's block has positive_length_measures: one of no or negative size is no
                    // stock, and the box of its corners would put material where the file does not
                    warnings.add("#" + blk.id() + " BLOCK, the bounding geometry of workpiece '" + text(w, "its_id")
                            + "', is " + num(x) + " x " + num(y) + " x " + num(z)
                            + " mm, its lengths not all positive: not read, the stock is not known");
                }
            }
        }
        return new Workpiece(w.id(), text(w, "its_id"), material, num(w, "global_tolerance"), block);
    }

    /** A length as written, without a trailing ".0". */
    private static String num(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? Long.toString((long) d) : Double.toString(d);
    }

    private Setup setup(E s) throws StepParseException {
        Setup done = setups.get(s.id());
        if (done != null) {
            return done;
        }
        List<Setup.WorkpieceSetup> wps = new ArrayList<>();
        for (long id : refList(s, "its_workpiece_setup")) {
            Optional<E> ws = known(id);
            if (ws.isPresent() && ws.get().def.isA("WORKPIECE_SETUP")) {
                wps.add(new Setup.WorkpieceSetup(
                        refId(ws.get(), "its_workpiece").orElse(0L),
                        placementAttr(ws.get(), "its_origin").orElse(Transform3.IDENTITY)));
            }
        }
        Setup out = new Setup(
                s.id(),
                text(s, "its_id"),
                placementAttr(s, "its_origin").orElse(Transform3.IDENTITY),
                planeAttr(s, "its_secplane"),
                wps);
        setups.put(s.id(), out);
        return out;
    }

    private Workplan workplan(E w, Deque<Long> stack, Optional<Setup> inherited) throws StepParseException {
        if (stack.contains(w.id())) {
            List<Long> loop = new ArrayList<>();
            for (long id : stack) {
                loop.add(id);
                if (id == w.id()) {
                    break;
                }
            }
            throw error(
                    w,
                    "workplan contains itself (through " + (loop.size() > 10 ? loop.subList(0, 10) + "..." : loop)
                            + ")");
        }
        if (stack.size() >= MAX_WORKPLAN_NESTING) {
            throw error(w, "workplans are nested more than " + MAX_WORKPLAN_NESTING + " deep");
        }
        stack.push(w.id());
        Optional<Setup> own = Optional.empty();
        Optional<E> s = ref(w, "its_setup", "SETUP");
        if (s.isPresent()) {
            own = Optional.of(setup(s.get()));
        }
        Optional<Setup> effective = own.isPresent() ? own : inherited;
        List<Executable> elements = new ArrayList<>();
        for (long id : refList(w, "its_elements")) {
            Optional<E> x = known(id);
            if (x.isEmpty()) {
                elements.add(new Executable.Other(id, "", typeOf(id)));
            } else if (x.get().def.isA("WORKPLAN")) {
                elements.add(workplan(x.get(), stack, effective));
            } else if (x.get().def.isA("MACHINING_WORKINGSTEP")) {
                elements.add(workingstep(x.get(), effective));
            } else if (x.get().def.isA("EXECUTABLE")) {
                elements.add(new Executable.Other(
                        id, text(x.get(), "its_id"), x.get().name()));
            } else {
                throw error(w, "WORKPLAN.its_elements should list executables, found #" + id + " " + typeOf(id));
            }
        }
        stack.pop();
        return new Workplan(w.id(), text(w, "its_id"), elements, own);
    }

    private MachiningWorkingstep workingstep(E ws, Optional<Setup> setup) throws StepParseException {
        MachiningWorkingstep done = workingsteps.get(ws.id());
        if (done != null) {
            return done;
        }
        Optional<Long> fid = refId(ws, "its_feature");
        Optional<Long> oid = refId(ws, "its_operation");
        if (fid.isEmpty() || oid.isEmpty()) {
            throw error(ws, "a machining workingstep needs its_feature and its_operation");
        }
        Feature f = feature(ws, fid.get());
        Operation op = operation(ws, oid.get());
        Transform3 wpToSetup = Transform3.IDENTITY;
        if (setup.isPresent()) {
            Setup s = setup.get();
            Optional<Long> wpId = known(fid.get()).flatMap(fe -> {
                try {
                    return refId(fe, "its_workpiece");
                } catch (StepParseException ex) {
                    return Optional.empty();
                }
            });
            for (Setup.WorkpieceSetup w : s.workpieceSetups()) {
                if (wpId.isEmpty() || wpId.get() == w.workpieceInstanceId()) {
                    wpToSetup = w.origin();
                    break;
                }
            }
        }
        MachiningWorkingstep out = new MachiningWorkingstep(
                ws.id(), text(ws, "its_id"), planeAttr(ws, "its_secplane"), f, op, setup, wpToSetup);
        workingsteps.put(ws.id(), out);
        return out;
    }

    // ---- features and profiles ----

    private Feature feature(E owner, long id) throws StepParseException {
        Feature done = features.get(id);
        if (done != null) {
            return done;
        }
        Optional<E> k = known(id);
        Feature out;
        if (k.isEmpty()) {
            out = new Feature(
                    id,
                    Feature.FeatureType.OTHER,
                    typeOf(id),
                    "",
                    Transform3.IDENTITY,
                    OptionalDouble.empty(),
                    Optional.empty(),
                    Optional.empty(),
                    Optional.empty(),
                    OptionalDouble.empty(),
                    Optional.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty(),
                    List.of(),
                    List.of(),
                    List.of(),
                    Optional.empty());
        } else {
            E f = k.get();
            expectKind(owner, f, "MANUFACTURING_FEATURE", "its_feature should be a manufacturing feature");
            Feature.FeatureType type = kindOf(Feature.FeatureType.class, f.name(), Feature.FeatureType.OTHER);
            Transform3 placement = placementAttr(f, "feature_placement").orElse(Transform3.IDENTITY);
            Optional<Transform3> depthPlane = planeAttr(f, "depth");
            OptionalDouble depth = depthPlane.isPresent()
                    ? OptionalDouble.of(-depthPlane.get().translationPart().z() + 0.0)
                    : OptionalDouble.empty();
            String profileAttr = switch (f.name()) {
                case "CLOSED_POCKET", "GENERAL_OUTSIDE_PROFILE" -> "feature_boundary";
                case "OPEN_POCKET", "STEP" -> f.name().equals("STEP") ? "wall_boundary" : "open_boundary";
                case "BOSS" -> "its_boundary";
                case "SLOT" -> "swept_shape";
                case "PLANAR_FACE" -> "removal_boundary";
                default -> null;
            };
            Optional<Profile> profile = profileAttr == null ? Optional.empty() : profile(f, profileAttr, placement);
            String unread = f.name().equals("PLANAR_FACE")
                    ? "face_boundary"
                    : f.name().equals("OPEN_POCKET") ? "wall_boundary" : null;
            if (profile.isPresent()
                    && unread != null
                    && f.has(unread)
                    && refId(f, unread).isPresent()) {
                // a face bounded inside its removal rectangle, or an open pocket whose walls have
                // a shape of their own, would be milled past what the file keeps
                profile = Optional.of(new Profile.Other(
                        profile.get().entity() + (unread.equals("face_boundary") ? " within a " : " with a ") + unread
                                + " (" + typeOf(refId(f, unread).get()) + ")",
                        profile.get().placement(),
                        id));
            }
            boolean boss = f.name().equals("BOSS");
            if (profile.isPresent() && (f.def.isA("POCKET") || boss) && f.has("slope")) {
                OptionalDouble slope = num(f, "slope");
                if (slope.isPresent() && Math.abs(slope.getAsDouble()) > 1e-9) {
                    // the planner mills a pocket's walls and a boss's flanks upright: walls that
                    // slope (a mould's draft) would be cut away below the top, flanks that lean
                    // would be cut away, so the outline is bound as one it refuses, with why
                    profile = Optional.of(new Profile.Other(
                            profile.get().entity() + (boss ? " with flanks leaning " : " with walls sloping ")
                                    + java.math.BigDecimal.valueOf(degrees(slope.getAsDouble()))
                                            .stripTrailingZeros()
                                            .toPlainString()
                                    + " deg from upright (slope)",
                            profile.get().placement(),
                            id));
                }
            }
            String travelAttr = f.name().equals("STEP") ? "open_boundary" : "course_of_travel";
            Optional<TravelPath> travel = f.has(travelAttr) ? travel(f, travelAttr) : Optional.empty();
            Optional<String> bottom = Optional.empty();
            if (f.has("bottom_condition")) {
                bottom = refId(f, "bottom_condition").map(this::typeOf);
            }
            out = new Feature(
                    id,
                    type,
                    f.name(),
                    text(f, "its_id"),
                    placement,
                    depth,
                    depthPlane,
                    profile,
                    travel,
                    f.has("diameter") ? num(f, "diameter") : OptionalDouble.empty(),
                    bottom,
                    f.has("planar_radius") ? num(f, "planar_radius") : OptionalDouble.empty(),
                    f.has("orthogonal_radius") ? num(f, "orthogonal_radius") : OptionalDouble.empty(),
                    refList(f, "its_operations"),
                    f.name().equals("SLOT") && f.has("end_conditions") ? slotEnds(f) : List.of(),
                    bosses(f),
                    f.has("change_in_diameter") ? taper(f) : Optional.empty());
        }
        features.put(id, out);
        return out;
    }

    /** A round hole's change_in_diameter (taper_select), when it gives one. */
    private Optional<Feature.HoleTaper> taper(E f) throws StepParseException {
        Optional<Long> id = refId(f, "change_in_diameter");
        if (id.isEmpty()) {
            return Optional.empty();
        }
        Optional<E> k = known(id.get());
        String name = k.map(E::name).orElse(typeOf(id.get()));
        if (k.isPresent() && name.equals("DIAMETER_TAPER") && k.get().has("final_diameter")) {
            return Optional.of(new Feature.HoleTaper(name, num(k.get(), "final_diameter"), OptionalDouble.empty()));
        }
        if (k.isPresent() && name.equals("ANGLE_TAPER") && k.get().has("angle")) {
            OptionalDouble a = num(k.get(), "angle");
            return Optional.of(new Feature.HoleTaper(
                    name, OptionalDouble.empty(), a.isPresent() ? OptionalDouble.of(degrees(a.getAsDouble())) : a));
        }
        return Optional.of(new Feature.HoleTaper(name, OptionalDouble.empty(), OptionalDouble.empty()));
    }

    /** A feature's its_boss, each bound as a feature of its own. */
    private List<Feature> bosses(E f) throws StepParseException {
        if (!f.has("its_boss")) {
            return List.of();
        }
        List<Feature> out = new ArrayList<>();
        for (long id : refList(f, "its_boss")) {
            out.add(feature(f, id));
        }
        return out;
    }

    private Optional<TravelPath> travel(E f, String attr) throws StepParseException {
        Optional<Long> id = refId(f, attr);
        if (id.isEmpty()) {
            return Optional.empty();
        }
        Optional<E> k = known(id.get());
        if (k.isPresent() && k.get().def.isA("GENERAL_PATH")) {
            E g = k.get();
            Profile c = curveProfile(g.name(), g.id(), Transform3.IDENTITY, refId(g, "swept_path"));
            return Optional.of(new TravelPath(
                    g.name(),
                    placementAttr(g, "placement").orElse(Transform3.IDENTITY),
                    OptionalDouble.empty(),
                    Optional.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty(),
                    c instanceof Profile.General curve ? curve.segments() : List.of()));
        }
        if (k.isEmpty() || !(k.get().def.isA("LINEAR_PATH") || k.get().def.isA("CIRCULAR_PATH"))) {
            return Optional.of(new TravelPath(
                    typeOf(id.get()),
                    Transform3.IDENTITY,
                    OptionalDouble.empty(),
                    Optional.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty()));
        }
        E p = k.get();
        Transform3 pl = placementAttr(p, "placement").orElse(Transform3.IDENTITY);
        if (p.def.isA("LINEAR_PATH")) {
            return Optional.of(new TravelPath(
                    p.name(),
                    pl,
                    num(p, "distance"),
                    directionAttr(p, "its_direction"),
                    OptionalDouble.empty(),
                    OptionalDouble.empty()));
        }
        return Optional.of(new TravelPath(
                p.name(), pl, OptionalDouble.empty(), Optional.empty(), num(p, "radius"), num(p, "sweep_angle")));
    }

    private Optional<Profile> profile(E f, String attr, Transform3 featurePlacement) throws StepParseException {
        Optional<Long> id = refId(f, attr);
        if (id.isEmpty()) {
            return Optional.empty();
        }
        Optional<E> k = known(id.get());
        if (k.isEmpty()) {
            return Optional.of(new Profile.Other(typeOf(id.get()), Transform3.IDENTITY, id.get()));
        }
        E p = k.get();
        if (!p.def.isA("PROFILE")) {
            throw error(f, f.name() + "." + attr + " should be a profile, found #" + id.get() + " " + p.name());
        }
        Transform3 pl = placementAttr(p, "placement").orElse(Transform3.IDENTITY);
        if (!pl.equals(Transform3.IDENTITY) && pl.eq(featurePlacement, SAME_FRAME)) {
            // GRIMA's writers repeat the feature placement here, in the workpiece frame; ISO
            // means a frame relative to the feature, so the repetition stands for the feature frame
            spellings.add("profile placements repeat their feature's placement (read as the feature frame)");
            pl = Transform3.IDENTITY;
        }
        Profile out = switch (p.name()) {
            case "RECTANGULAR_CLOSED_PROFILE" ->
                new Profile.Rectangular(p.name(), pl, required(p, "profile_width"), required(p, "profile_length"));
            case "CIRCULAR_CLOSED_PROFILE" -> new Profile.Circular(p.name(), pl, required(p, "diameter"));
            case "NGON_PROFILE" -> {
                OptionalInt n = integer(p, "number_of_sides");
                if (n.isEmpty() || n.getAsInt() < 3) {
                    throw error(p, "NGON_PROFILE.number_of_sides must be at least 3");
                }
                yield new Profile.Ngon(
                        p.name(),
                        pl,
                        required(p, "diameter"),
                        n.getAsInt(),
                        bool(p, "circumscribed_or_across_flats").orElse(false));
            }
            case "LINEAR_PROFILE" -> new Profile.Linear(p.name(), pl, required(p, "profile_length"));
            case "SQUARE_U_PROFILE" ->
                new Profile.U(
                        p.name(),
                        pl,
                        required(p, "width"),
                        num(p, "first_radius"),
                        degrees(num(p, "first_angle")),
                        num(p, "second_radius"),
                        degrees(num(p, "second_angle")));
            case "ROUNDED_U_PROFILE" ->
                new Profile.U(
                        p.name(),
                        pl,
                        required(p, "width"),
                        OptionalDouble.empty(),
                        OptionalDouble.empty(),
                        OptionalDouble.empty(),
                        OptionalDouble.empty());
            case "VEE_PROFILE" ->
                new Profile.Vee(
                        p.name(),
                        pl,
                        num(p, "profile_radius"),
                        degrees(required(p, "profile_angle")),
                        degrees(required(p, "tilt_angle")));
            case "TEE_PROFILE" ->
                new Profile.Tee(
                        p.name(),
                        pl,
                        required(p, "width"),
                        required(p, "cross_bar_width"),
                        required(p, "cross_bar_depth"),
                        num(p, "radius"),
                        degrees(required(p, "first_angle")),
                        degrees(required(p, "second_angle")));
            case "PARTIAL_CIRCULAR_PROFILE" ->
                new Profile.PartialCircular(p.name(), pl, required(p, "radius"), degrees(required(p, "sweep_angle")));
            case "GENERAL_CLOSED_PROFILE", "GENERAL_PROFILE" ->
                general(p, pl, p.name().equals("GENERAL_PROFILE") ? "its_profile" : "closed_profile_shape");
            default -> new Profile.Other(p.name(), pl, p.id());
        };
        return Optional.of(out);
    }

    /** A plane angle as the file writes it, in degrees (STEP Modeler writes radians). */
    private double degrees(double written) {
        return dialect == Dialect.STEP_MODELER ? Math.toDegrees(written) : written;
    }

    private OptionalDouble degrees(OptionalDouble written) {
        return written.isPresent() ? OptionalDouble.of(degrees(written.getAsDouble())) : written;
    }

    /** A slot's end_conditions, in file order. */
    private List<Feature.SlotEnd> slotEnds(E f) throws StepParseException {
        List<Feature.SlotEnd> out = new ArrayList<>();
        for (long id : refList(f, "end_conditions")) {
            Optional<E> k = known(id);
            String name = k.map(E::name).orElse(typeOf(id));
            Feature.SlotEnd.EndType type = switch (name) {
                case "OPEN_SLOT_END_TYPE" -> Feature.SlotEnd.EndType.OPEN;
                case "RADIUSED_SLOT_END_TYPE" -> Feature.SlotEnd.EndType.RADIUSED;
                case "FLAT_SLOT_END_TYPE" -> Feature.SlotEnd.EndType.FLAT;
                case "LOOP_SLOT_END_TYPE" -> Feature.SlotEnd.EndType.LOOP;
                case "WOODRUFF_SLOT_END_TYPE" -> Feature.SlotEnd.EndType.WOODRUFF;
                default -> Feature.SlotEnd.EndType.OTHER;
            };
            OptionalDouble first = OptionalDouble.empty();
            OptionalDouble second = OptionalDouble.empty();
            if (k.isPresent() && type == Feature.SlotEnd.EndType.FLAT) {
                first = num(k.get(), "corner_radius1");
                second = num(k.get(), "corner_radius2");
            } else if (k.isPresent() && type == Feature.SlotEnd.EndType.WOODRUFF) {
                first = num(k.get(), "radius");
            }
            out.add(new Feature.SlotEnd(type, name, first, second));
        }
        return out;
    }

    private Profile general(E p, Transform3 pl, String attr) throws StepParseException {
        return curveProfile(p.name(), p.id(), pl, refId(p, attr));
    }

    /**
     * A POLYLINE or COMPOSITE_CURVE as a general profile of the given entity; {@link Profile.Other}
     * when the curve is missing or of another kind.
     */
    Profile curveProfile(String entity, long ownerId, Transform3 pl, Optional<Long> cid) throws StepParseException {
        Optional<E> c = cid.flatMap(this::known);
        if (c.isEmpty()) {
            return new Profile.Other(entity, pl, ownerId);
        }
        List<Profile.Segment> segs = new ArrayList<>();
        if (c.get().def.isA("POLYLINE")) {
            List<Vec3> pts = new ArrayList<>();
            for (long id : refList(c.get(), "points")) {
                Optional<E> pt = known(id);
                if (pt.isEmpty()) {
                    throw error(
                            c.get(), "POLYLINE.points should list CARTESIAN_POINTs, found #" + id + " " + typeOf(id));
                }
                pts.add(point(pt.get()));
            }
            for (int i = 0; i + 1 < pts.size(); i++) {
                segs.add(new Profile.Line(pts.get(i), pts.get(i + 1)));
            }
        } else if (c.get().def.isA("COMPOSITE_CURVE")) {
            for (long id : refList(c.get(), "segments")) {
                Optional<Profile.Segment> s = compositeSegment(id);
                if (s.isEmpty()) {
                    warnings.add("#" + ownerId + " " + entity + ": composite curve segment #" + id
                            + " is not a trimmed line or circle with point trims; the profile is kept raw");
                    return new Profile.Other(entity, pl, ownerId);
                }
                segs.add(s.get());
            }
        } else {
            return new Profile.Other(entity, pl, ownerId);
        }
        boolean closed = !segs.isEmpty()
                && segs.get(0).start().distance(segs.get(segs.size() - 1).end()) <= 1e-9;
        return new Profile.General(entity, pl, c.get().name(), segs, closed);
    }

    private Optional<Profile.Segment> compositeSegment(long id) throws StepParseException {
        Optional<E> seg = known(id);
        if (seg.isEmpty() || !seg.get().def.isA("COMPOSITE_CURVE_SEGMENT")) {
            return Optional.empty();
        }
        boolean sameSense = bool(seg.get(), "same_sense").orElse(true);
        Optional<E> tc = refId(seg.get(), "parent_curve").flatMap(this::known);
        if (tc.isEmpty() || !tc.get().def.isA("TRIMMED_CURVE")) {
            return Optional.empty();
        }
        E t = tc.get();
        Optional<Vec3> p1 = trimPoint(t, "trim_1");
        Optional<Vec3> p2 = trimPoint(t, "trim_2");
        Optional<E> basis = refId(t, "basis_curve").flatMap(this::known);
        if (p1.isEmpty() || p2.isEmpty() || basis.isEmpty()) {
            return Optional.empty();
        }
        boolean sense = bool(t, "sense_agreement").orElse(true);
        Vec3 a = sense ? p1.get() : p2.get();
        Vec3 b = sense ? p2.get() : p1.get();
        if (!sameSense) {
            Vec3 x = a;
            a = b;
            b = x;
        }
        if (basis.get().def.isA("LINE") || basis.get().def.isA("POLYLINE")) {
            return Optional.of(new Profile.Line(a, b));
        }
        if (basis.get().def.isA("CIRCLE")) {
            E circle = basis.get();
            Transform3 frame = placementAttr(circle, "position").orElse(Transform3.IDENTITY);
            boolean ccw = frame.zAxis().z() >= 0;
            // the circle runs counterclockwise about its own axis; the trimmed part follows the sense
            if (!sense) {
                ccw = !ccw;
            }
            if (!sameSense) {
                ccw = !ccw;
            }
            return Optional.of(new Profile.Arc(a, b, frame.translationPart(), required(circle, "radius"), ccw));
        }
        return Optional.empty();
    }

    private Optional<Vec3> trimPoint(E t, String attr) throws StepParseException {
        StepValue v = t.v(attr);
        if (v instanceof StepValue.Aggregate a) {
            for (StepValue item : a.items()) {
                if (item instanceof StepValue.Ref r) {
                    Optional<E> p = known(r.id());
                    if (p.isPresent() && p.get().def.isA("CARTESIAN_POINT")) {
                        return Optional.of(point(p.get()));
                    }
                }
            }
        }
        return Optional.empty();
    }

    // ---- operations ----

    private Operation operation(E owner, long id) throws StepParseException {
        Optional<E> k = known(id);
        if (k.isEmpty()) {
            return new Operation(
                    id,
                    Operation.OperationType.OTHER,
                    typeOf(id),
                    "",
                    OptionalDouble.empty(),
                    Optional.empty(),
                    Optional.empty(),
                    Technology.NONE,
                    Optional.empty(),
                    Optional.empty(),
                    Optional.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty(),
                    Optional.empty(),
                    List.of());
        }
        E o = k.get();
        expectKind(owner, o, "MACHINING_OPERATION", "its_operation should be a machining operation");
        Operation.OperationType type = kindOf(Operation.OperationType.class, o.name(), Operation.OperationType.OTHER);
        Optional<Tool> tool = Optional.empty();
        Optional<Long> toolId = refId(o, "its_tool");
        if (toolId.isPresent()) {
            tool = tool(o, toolId.get());
        }
        Technology tech = Technology.NONE;
        Optional<E> t = ref(o, "its_technology", "MILLING_TECHNOLOGY");
        if (t.isPresent()) {
            tech = technology(t.get());
        }
        OptionalDouble diameter = tool.map(Tool::diameterMm).orElse(OptionalDouble.empty());
        Optional<Strategy> strategy = Optional.empty();
        if (o.has("its_machining_strategy")) {
            Optional<Long> sid = refId(o, "its_machining_strategy");
            if (sid.isPresent()) {
                strategy = Optional.of(strategy(o, sid.get(), diameter));
            }
        }
        return new Operation(
                id,
                type,
                o.name(),
                text(o, "its_id"),
                num(o, "retract_plane"),
                pointAttr(o, "start_point"),
                tool,
                tech,
                strategy,
                approach(o, "approach"),
                approach(o, "retract"),
                num(o, "axial_cutting_depth"),
                num(o, "radial_cutting_depth"),
                num(o, "allowance_side"),
                num(o, "allowance_bottom"),
                num(o, "cutting_depth"),
                num(o, "overcut_length"),
                o.def.isA("DRILLING_TYPE_OPERATION") ? Optional.of(drillingParameters(o)) : Optional.empty(),
                List.of());
    }

    // ISO 14649-11 drilling_type_operation, multistep_drilling, boring_operation
    private DrillingParameters drillingParameters(E o) throws StepParseException {
        OptionalDouble feedOnRetract = num(o, "feed_on_retract");
        if (feedOnRetract.isPresent() && feedOnRetract.getAsDouble() > 1) {
            feedOnRetract = OptionalDouble.of(feedOnRetract.getAsDouble() / 100);
        }
        return new DrillingParameters(
                num(o, "dwell_time_bottom"),
                feedOnRetract,
                num(o, "retract_distance"),
                num(o, "first_depth"),
                num(o, "depth_of_step"),
                num(o, "dwell_time_step"),
                bool(o, "spindle_stop_at_bottom"));
    }

    private Optional<ApproachRetract> approach(E o, String attr) throws StepParseException {
        if (!o.has(attr)) {
            return Optional.empty();
        }
        Optional<Long> id = refId(o, attr);
        if (id.isEmpty()) {
            return Optional.empty();
        }
        Optional<E> k = known(id.get());
        if (k.isEmpty() || !k.get().def.isA("APPROACH_RETRACT_STRATEGY")) {
            return Optional.of(new ApproachRetract(
                    id.get(),
                    ApproachRetract.Kind.OTHER,
                    typeOf(id.get()),
                    Optional.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty(),
                    OptionalDouble.empty()));
        }
        E a = k.get();
        ApproachRetract.Kind kind = kindOf(ApproachRetract.Kind.class, a.name(), ApproachRetract.Kind.OTHER);
        return Optional.of(new ApproachRetract(
                a.id(),
                kind,
                a.name(),
                directionAttr(a, "tool_orientation"),
                num(a, "angle"),
                num(a, "radius"),
                num(a, "width")));
    }

    private Strategy strategy(E owner, long id, OptionalDouble toolDiameter) throws StepParseException {
        Optional<E> k = known(id);
        if (k.isEmpty()) {
            return withoutMillingParameters(id, Strategy.StrategyType.OTHER, typeOf(id), Optional.empty());
        }
        E s = k.get();
        Strategy.StrategyType type = switch (s.name()) {
            case "UNIDIRECTIONAL_MILLING" -> Strategy.StrategyType.UNIDIRECTIONAL;
            case "BIDIRECTIONAL_MILLING" -> Strategy.StrategyType.BIDIRECTIONAL;
            case "EXPLICIT_STRATEGY" -> Strategy.StrategyType.EXPLICIT;
            case "CONTOUR_PARALLEL",
                    "CONTOUR_SPIRAL",
                    "BIDIRECTIONAL_CONTOUR",
                    "CONTOUR_BIDIRECTIONAL",
                    "CENTER_MILLING",
                    "DRILLING_TYPE_STRATEGY" -> Strategy.StrategyType.valueOf(s.name());
            default -> throw error(owner, "its_machining_strategy should be a strategy, found #" + id + " " + s.name());
        };
        String spelling = s.inst.record().type();
        if (type == Strategy.StrategyType.DRILLING_TYPE_STRATEGY) {
            OptionalDouble[] ratios = new OptionalDouble[4];
            List<String> names = List.of(
                    "reduced_cut_at_start", "reduced_feed_at_start", "reduced_cut_at_end", "reduced_feed_at_end");
            for (int i = 0; i < ratios.length; i++) {
                OptionalDouble v = num(s, names.get(i));
                if (v.isPresent() && v.getAsDouble() > 1) {
                    spellings.add("DRILLING_TYPE_STRATEGY ratios written as percentages (0-100)");
                    v = OptionalDouble.of(v.getAsDouble() / 100);
                } else if (v.isPresent()) {
                    spellings.add("DRILLING_TYPE_STRATEGY ratios written as fractions (0-1)");
                }
                ratios[i] = v;
            }
            DrillingStrategy d = new DrillingStrategy(
                    ratios[0], ratios[1], num(s, "depth_of_start"), ratios[2], ratios[3], num(s, "depth_of_end"));
            return withoutMillingParameters(id, type, spelling, Optional.of(d));
        }
        OptionalDouble overlap = num(s, "overlap");
        OptionalDouble fraction = OptionalDouble.empty();
        Optional<String> how = Optional.empty();
        if (overlap.isPresent()) {
            double v = overlap.getAsDouble();
            if (v >= 0 && v <= 1) {
                fraction = OptionalDouble.of(v);
                how = Optional.of("fraction");
            } else if (dialect == Dialect.STEP_MODELER
                    && toolDiameter.isPresent()
                    && v > 0
                    && v < toolDiameter.getAsDouble()) {
                fraction = OptionalDouble.of(v / toolDiameter.getAsDouble());
                how = Optional.of("length");
            } else if (v > 1 && v <= 100) {
                fraction = OptionalDouble.of(v / 100);
                how = Optional.of("percent");
            } else {
                warnings.add("#" + id + " " + spelling + ": overlap " + v + " is neither a fraction nor a percentage");
                how = Optional.of("unreadable");
            }
            spellings.add(
                    switch (how.get()) {
                        case "fraction" -> "strategy overlap written as a fraction of the tool diameter (0-1)";
                        case "percent" -> "strategy overlap written as a percentage of the tool diameter (0-100)";
                        case "length" -> "strategy overlap written as a length in mm (STEP Modeler)";
                        default -> "strategy overlap out of range";
                    });
        }
        return new Strategy(
                id,
                type,
                spelling,
                overlap,
                fraction,
                how,
                bool(s, "allow_multiple_passes"),
                directionAttr(s, "feed_direction"),
                enumeration(s, "stepover_direction"),
                enumeration(s, "rotation_direction"),
                s.has("spiral_cutmode") ? enumeration(s, "spiral_cutmode") : enumeration(s, "cutmode"),
                Optional.empty());
    }

    private Optional<Tool> tool(E owner, long id) throws StepParseException {
        Tool done = tools.get(id);
        if (done != null) {
            return Optional.of(done);
        }
        Optional<E> k = known(id);
        if (k.isEmpty()) {
            return Optional.empty();
        }
        E t = k.get();
        expectKind(owner, t, "MACHINING_TOOL", "its_tool should be a cutting tool");
        String body = "";
        String dimEntity = "";
        OptionalDouble[] dims = new OptionalDouble[7];
        java.util.Arrays.fill(dims, OptionalDouble.empty());
        OptionalInt teeth = OptionalInt.empty();
        Optional<String> hand = Optional.empty();
        OptionalDouble pilot = OptionalDouble.empty();
        Optional<Long> bodyId = t.has("its_tool_body") ? refId(t, "its_tool_body") : Optional.empty();
        if (bodyId.isPresent()) {
            body = typeOf(bodyId.get());
            Optional<E> b = known(bodyId.get());
            if (b.isPresent() && b.get().def.isA("MILLING_TOOL_BODY")) {
                E tb = b.get();
                teeth = integer(tb, "number_of_teeth");
                hand = enumeration(tb, "hand_of_cut");
                pilot = num(tb, "pilot_length");
                Optional<E> d = ref(tb, "dimension", "MILLING_TOOL_DIMENSION");
                if (d.isPresent()) {
                    dimEntity = d.get().inst.record().type();
                    String[] names = {
                        "diameter",
                        "tool_top_angle",
                        "tool_circumference_angle",
                        "cutting_edge_length",
                        "edge_radius",
                        "edge_center_vertical",
                        "edge_center_horizontal"
                    };
                    for (int i = 0; i < names.length; i++) {
                        dims[i] = num(d.get(), names[i]);
                    }
                }
            } else if (b.isPresent()) {
                throw error(
                        t,
                        "its_tool_body should be a tool body, found #" + bodyId.get() + " "
                                + b.get().name());
            }
        }
        OptionalDouble offset = OptionalDouble.empty();
        if (t.has("its_cutting_edge")) {
            for (long cc : refList(t, "its_cutting_edge")) {
                Optional<E> c = known(cc);
                if (c.isPresent() && c.get().def.isA("CUTTING_COMPONENT")) {
                    offset = num(c.get(), "tool_offset_length");
                    break;
                }
            }
        }
        Tool out = new Tool(
                id,
                text(t, "its_id"),
                body,
                dimEntity,
                dims[0],
                dims[1],
                dims[2],
                dims[3],
                dims[4],
                dims[5],
                dims[6],
                num(t, "overall_assembly_length"),
                offset,
                teeth,
                hand,
                pilot,
                dialect == Dialect.STEP_MODELER ? "rad" : "deg");
        tools.put(id, out);
        return Optional.of(out);
    }

    private Technology technology(E t) throws StepParseException {
        OptionalDouble feed = num(t, "feedrate");
        OptionalDouble cut = num(t, "cutspeed");
        OptionalDouble spindle = num(t, "spindle");
        boolean iso = dialect == Dialect.ISO_14649;
        OptionalDouble feedMmMin =
                iso && feed.isPresent() ? OptionalDouble.of(feed.getAsDouble() * 60000) : OptionalDouble.empty();
        OptionalDouble rpm = spindle.isPresent()
                ? OptionalDouble.of(Math.abs(spindle.getAsDouble()) * (iso ? 60 : 1))
                : OptionalDouble.empty();
        boolean cw = spindle.isPresent() && spindle.getAsDouble() < 0;
        return new Technology(
                t.id(),
                feed,
                iso ? "m/s" : "unstated",
                enumeration(t, "feedrate_reference"),
                cut,
                iso ? "m/s" : "m/min",
                spindle,
                iso ? "1/s" : "rpm",
                num(t, "feed_per_tooth"),
                feedMmMin,
                rpm,
                cw);
    }

    /** Unknown entity types by count, for reports (kept for the GUI). */
    static Map<String, Integer> sortedByCount(Map<String, Integer> m) {
        Map<String, Integer> out = new LinkedHashMap<>();
        m.entrySet().stream()
                .sorted((a, b) -> b.getValue() - a.getValue())
                .forEach(e -> out.put(e.getKey(), e.getValue()));
        return out;
    }
}
