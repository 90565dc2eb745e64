package org.fresa.stepnc;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
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
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.stepnc.StepNcProgram.Dialect;

/**
 * Turns an AP238 file in its integrated form (AIM: schema MODEL_BASED_INTEGRATED_MANUFACTURING_SCHEMA
 * or INTEGRATED_CNC_SCHEMA, as STEP Tools' software writes it) into the same ISO 14649 model as
 * {@link Iso14649Binder}. In the AIM an ARM object is a generic STEP resource tied to its values
 * by relationships, so this binder walks references backwards:
 * <ul>
 * <li>workplans and workingsteps are {@code action_method}s (MACHINING_WORKPLAN,
 * MACHINING_WORKINGSTEP, PLANE_MILLING_OPERATION ... with name, description, consequence,
 * purpose); a workplan's elements are the MACHINING_PROCESS_SEQUENCE_RELATIONSHIPs that relate
 * it, in sequence_position order; the feature, operation, tool, technology and strategies of a
 * workingstep or operation are MACHINING_*_RELATIONSHIPs;
 * <li>the attributes of an action are ACTION_PROPERTY (by name) - ACTION_PROPERTY_REPRESENTATION
 * - REPRESENTATION items: measures with their units, descriptive texts, directions, planes;
 * <li>features are complex instances (INSTANCED_FEATURE with ROUND_HOLE, POCKET, FLAT_FACE ...)
 * whose placement and depth are shape representations of their PRODUCT_DEFINITION_SHAPE, and
 * whose profiles, paths and bottoms are SHAPE_ASPECTs ("... occurrence") related to components;
 * <li>the project, setup and workpieces are PRODUCT_DEFINITIONs of a MACHINING_PROJECT or
 * MACHINING_SETUP product; a workpiece's bounding block is the BLOCK_SHAPE_REPRESENTATION of what
 * it is made from (MAKE_FROM_USAGE_OPTION).
 * </ul>
 * The descriptions of generic entities carry the ARM kind (PLANE_MILLING_OPERATION 'finishing'
 * is plane_finish_milling, BORING_OPERATION 'reaming' is reaming). Every measure is converted by
 * its own unit (SI prefixes, CONVERSION_BASED_UNIT such as the inch, DERIVED_UNIT for feeds and
 * speeds) into the model's units (mm, mm/min, rpm, degrees, seconds); coordinates of points and
 * placements are in the length unit of the file's GLOBAL_UNIT_ASSIGNED_CONTEXT. The geometry
 * itself (points, directions, placements, planes, polylines, composite curves) is bound by
 * {@link Iso14649Binder}: its entities are the same in both forms.
 */
final class Ap238AimBinder {

    /** Feeds below this (mm/min) are reported as doubtful: no cutting feed is that slow. */
    static final double SLOWEST_PLAUSIBLE_FEED = 10;

    /** A slot profile's 'depth' and the slot's maximum feature limit agree within this (mm). */
    static final double SAME_DEPTH_MM = 1e-6;

    private static final Set<String> FEATURE_NOISE = Set.of(
            "CHARACTERIZED_OBJECT",
            "FEATURE_DEFINITION",
            "INSTANCED_FEATURE",
            "SHAPE_ASPECT",
            "SHAPE_FEATURE_DEFINITION");

    private final StepFile file;
    private final Iso14649Binder geometry;
    private final Map<Long, List<Long>> users = new HashMap<>();
    private final Set<String> spellings = new LinkedHashSet<>();
    private final List<String> warnings = new ArrayList<>();
    private final Map<Long, Feature> features = new HashMap<>();
    private final Map<Long, Tool> tools = new HashMap<>();
    private final Map<Long, MachiningWorkingstep> workingsteps = new HashMap<>();
    /** Millimetres per unit of the file's global length unit. */
    private double lengthScale = 1;

    private String lengthUnitName = "mm";

    Ap238AimBinder(StepFile file) {
        this.file = file;
        this.geometry = new Iso14649Binder(file);
    }

    /** The FILE_SCHEMA names that mark the integrated form. */
    static boolean isIntegrated(List<String> schemas) {
        return schemas.stream()
                .map(s -> s.toUpperCase(Locale.ROOT))
                .anyMatch(s -> s.startsWith("MODEL_BASED_INTEGRATED_MANUFACTURING_SCHEMA")
                        || s.startsWith("INTEGRATED_CNC_SCHEMA"));
    }

    // ---- raw access ----

    private StepInstance inst(long id) {
        return file.instance(id).orElse(null);
    }

    /** The record of this type in the instance (its only record, or its partial record). */
    private Optional<StepRecord> rec(long id, String type) {
        StepInstance i = inst(id);
        if (i == null) {
            return Optional.empty();
        }
        return i.part(type);
    }

    private boolean isA(long id, String type) {
        return rec(id, type).isPresent();
    }

    private String typeOf(long id) {
        StepInstance i = inst(id);
        return i == null ? "?" : i.type();
    }

    private static Optional<Long> ref(StepValue v) {
        return v instanceof StepValue.Ref r ? Optional.of(r.id()) : Optional.empty();
    }

    private static String text(StepValue v) {
        return v instanceof StepValue.Text t ? t.value() : "";
    }

    private static List<Long> refs(StepValue v) {
        List<Long> out = new ArrayList<>();
        collectRefs(v, out, 0);
        return out;
    }

    private static void collectRefs(StepValue v, List<Long> out, int depth) {
        if (v instanceof StepValue.Ref r) {
            out.add(r.id());
        } else if (v instanceof StepValue.Aggregate a && depth < 8) {
            for (StepValue x : a.items()) {
                collectRefs(x, out, depth + 1);
            }
        } else if (v instanceof StepValue.Typed t && depth < 8) {
            collectRefs(t.value(), out, depth + 1);
        }
    }

    /** Instances of the given type whose attribute at {@code index} references {@code target}. */
    private List<Long> usersOf(long target, String type, int index) {
        List<Long> out = new ArrayList<>();
        for (long u : users.getOrDefault(target, List.of())) {
            Optional<StepRecord> r = rec(u, type);
            if (r.isPresent() && refs(r.get().param(index)).contains(target) && !out.contains(u)) {
                out.add(u);
            }
        }
        return out;
    }

    private Optional<Long> firstUser(long target, String type, int index) {
        List<Long> u = usersOf(target, type, index);
        return u.isEmpty() ? Optional.empty() : Optional.of(u.get(0));
    }

    private StepParseException error(long id, String problem) {
        StepInstance i = inst(id);
        return new StepParseException(file.source(), i == null ? 0 : i.line(), i == null ? 0 : i.column(), id, problem);
    }

    // ---- units ----

    /** What a unit measures and how many model units (mm, s, deg, 1) one of it is. */
    private record Unit(double factor, String label) {}

    private Unit unit(long id, int depth) {
        if (depth > 8 || inst(id) == null) {
            return new Unit(1, "");
        }
        Optional<StepRecord> si = rec(id, "SI_UNIT");
        if (si.isPresent()) {
            double prefix = prefix(si.get().param(0));
            String name = si.get().param(1) instanceof StepValue.Enumeration e ? e.name() : "";
            String p = prefixLabel(si.get().param(0));
            return switch (name) {
                case "METRE" -> new Unit(prefix * 1000, p + "m");
                case "SECOND" -> new Unit(prefix, p + "s");
                case "RADIAN" -> new Unit(prefix * 180 / Math.PI, p + "rad");
                default -> new Unit(prefix, p + name.toLowerCase(Locale.ROOT));
            };
        }
        Optional<StepRecord> cb = rec(id, "CONVERSION_BASED_UNIT");
        if (cb.isPresent()) {
            String name = text(cb.get().param(0));
            Optional<Long> mwu = ref(cb.get().param(1));
            if (mwu.isPresent()) {
                Optional<double[]> v = measureWithUnit(mwu.get(), depth + 1);
                if (v.isPresent()) {
                    return new Unit(v.get()[0], name);
                }
            }
            warnings.add("#" + id + " CONVERSION_BASED_UNIT '" + name + "' has no usable conversion factor; read as 1");
            return new Unit(1, name);
        }
        Optional<StepRecord> du = rec(id, "DERIVED_UNIT");
        if (du.isPresent()) {
            double f = 1;
            StringBuilder num = new StringBuilder();
            StringBuilder den = new StringBuilder();
            for (long e : refs(du.get().param(0))) {
                Optional<StepRecord> el = rec(e, "DERIVED_UNIT_ELEMENT");
                if (el.isEmpty()) {
                    continue;
                }
                double exp = number(el.get().param(1)).orElse(1);
                Unit u = ref(el.get().param(0)).map(x -> unit(x, depth + 1)).orElse(new Unit(1, ""));
                f *= Math.pow(u.factor(), exp);
                String l = u.label() + (Math.abs(exp) == 1 ? "" : "^" + num(Math.abs(exp)));
                (exp < 0 ? den : num)
                        .append(exp < 0 ? (den.length() > 0 ? "*" : "") : (num.length() > 0 ? "*" : ""))
                        .append(l);
            }
            String label = (num.length() == 0 ? "1" : num) + (den.length() == 0 ? "" : "/" + den);
            return new Unit(f, label);
        }
        return new Unit(1, "");
    }

    private static String num(double d) {
        return d == Math.rint(d) ? Long.toString((long) d) : Double.toString(d);
    }

    private static double prefix(StepValue v) {
        if (!(v instanceof StepValue.Enumeration e)) {
            return 1;
        }
        return switch (e.name()) {
            case "EXA" -> 1e18;
            case "PETA" -> 1e15;
            case "TERA" -> 1e12;
            case "GIGA" -> 1e9;
            case "MEGA" -> 1e6;
            case "KILO" -> 1e3;
            case "HECTO" -> 1e2;
            case "DECA" -> 1e1;
            case "DECI" -> 1e-1;
            case "CENTI" -> 1e-2;
            case "MILLI" -> 1e-3;
            case "MICRO" -> 1e-6;
            case "NANO" -> 1e-9;
            case "PICO" -> 1e-12;
            case "FEMTO" -> 1e-15;
            case "ATTO" -> 1e-18;
            default -> 1;
        };
    }

    private static String prefixLabel(StepValue v) {
        if (!(v instanceof StepValue.Enumeration e)) {
            return "";
        }
        return switch (e.name()) {
            case "KILO" -> "k";
            case "DECI" -> "d";
            case "CENTI" -> "c";
            case "MILLI" -> "m";
            case "MICRO" -> "u";
            default -> e.name().toLowerCase(Locale.ROOT) + " ";
        };
    }

    private static OptionalDouble number(StepValue v) {
        if (v instanceof StepValue.Real r) {
            return OptionalDouble.of(r.value());
        }
        if (v instanceof StepValue.Int i) {
            return OptionalDouble.of(i.value());
        }
        if (v instanceof StepValue.Typed t) {
            return number(t.value());
        }
        return OptionalDouble.empty();
    }

    /** A MEASURE_WITH_UNIT (simple or part of a complex instance): value times its unit's factor, and the unit's factor. */
    private Optional<double[]> measureWithUnit(long id, int depth) {
        StepInstance i = inst(id);
        if (i == null) {
            return Optional.empty();
        }
        StepRecord r = i.part("MEASURE_WITH_UNIT").orElse(i.isComplex() ? null : i.record());
        if (r == null) {
            return Optional.empty();
        }
        OptionalDouble v = number(r.param(0));
        if (v.isEmpty()) {
            return Optional.empty();
        }
        Unit u = ref(r.param(1)).map(x -> unit(x, depth + 1)).orElse(new Unit(1, ""));
        return Optional.of(new double[] {v.getAsDouble() * u.factor(), u.factor()});
    }

    /** The file's length unit, from the first GLOBAL_UNIT_ASSIGNED_CONTEXT that has one. */
    private void readLengthUnit() {
        Set<String> seen = new LinkedHashSet<>();
        boolean first = true;
        for (int k = 0; k < file.size(); k++) {
            StepInstance i = file.instanceAt(k);
            Optional<StepRecord> g = i.part("GLOBAL_UNIT_ASSIGNED_CONTEXT");
            if (g.isEmpty()) {
                continue;
            }
            for (long u : refs(g.get().param(0))) {
                if (isA(u, "LENGTH_UNIT")) {
                    Unit un = unit(u, 0);
                    seen.add(un.label());
                    if (first) {
                        lengthScale = un.factor();
                        lengthUnitName = un.label();
                        first = false;
                    }
                }
            }
        }
        if (seen.size() > 1) {
            warnings.add("the file's representation contexts give several length units " + seen
                    + "; coordinates read in " + lengthUnitName);
        }
        if (lengthScale != 1) {
            spellings.add("lengths in " + lengthUnitName + " (" + num(lengthScale) + " mm), converted to mm");
        }
    }

    // ---- values of representations ----

    /** One value of a representation item: a number in model units, a text, or a reference. */
    private record Item(long id, String name, OptionalDouble value, String text, String kind) {}

    private Item item(long id) {
        StepInstance i = inst(id);
        if (i == null) {
            return new Item(id, "", OptionalDouble.empty(), "", "?");
        }
        String name = i.part("REPRESENTATION_ITEM")
                .map(r -> text(r.param(0)))
                .orElse(i.isComplex() ? "" : text(i.record().param(0)));
        Optional<StepRecord> mwu = i.part("MEASURE_WITH_UNIT");
        if (mwu.isPresent()) {
            OptionalDouble v = number(mwu.get().param(0));
            Unit u = ref(mwu.get().param(1)).map(x -> unit(x, 0)).orElse(new Unit(1, ""));
            return new Item(
                    id, name, v.isPresent() ? OptionalDouble.of(v.getAsDouble() * u.factor()) : v, "", "measure");
        }
        Optional<StepRecord> mri = i.part("MEASURE_REPRESENTATION_ITEM");
        if (mri.isPresent() && !i.isComplex()) {
            OptionalDouble v = number(mri.get().param(1));
            Unit u = ref(mri.get().param(2)).map(x -> unit(x, 0)).orElse(new Unit(1, ""));
            return new Item(
                    id,
                    name,
                    v.isPresent() ? OptionalDouble.of(v.getAsDouble() * u.factor()) : v,
                    u.label(),
                    "measure");
        }
        Optional<StepRecord> d = i.part("DESCRIPTIVE_REPRESENTATION_ITEM");
        if (d.isPresent()) {
            return new Item(id, name, OptionalDouble.empty(), text(d.get().param(1)), "text");
        }
        return new Item(id, name, OptionalDouble.empty(), "", i.type());
    }

    private List<Long> items(long representation) {
        StepInstance i = inst(representation);
        if (i == null) {
            return List.of();
        }
        StepRecord r = i.isComplex() ? i.part("REPRESENTATION").orElse(i.record()) : i.record();
        return refs(r.param(1));
    }

    /** A property of an action (ACTION_PROPERTY name) with its representation's name and items. */
    private record Property(String name, String representationName, List<Long> items) {}

    private List<Property> actionProperties(long action) {
        List<Property> out = new ArrayList<>();
        for (long ap : usersOf(action, "ACTION_PROPERTY", 2)) {
            String name =
                    text(rec(ap, "ACTION_PROPERTY").orElseThrow().param(0)).toLowerCase(Locale.ROOT);
            for (long apr : usersOf(ap, "ACTION_PROPERTY_REPRESENTATION", 2)) {
                StepRecord r = rec(apr, "ACTION_PROPERTY_REPRESENTATION").orElseThrow();
                Optional<Long> rep = ref(r.param(3));
                out.add(new Property(
                        name,
                        text(r.param(0)).toLowerCase(Locale.ROOT),
                        rep.map(this::items).orElse(List.of())));
            }
        }
        return out;
    }

    private Optional<Property> property(List<Property> ps, String name) {
        return ps.stream().filter(p -> p.name().equals(name)).findFirst();
    }

    private Optional<Property> property(List<Property> ps, String name, String representation) {
        return ps.stream()
                .filter(p -> p.name().equals(name) && p.representationName().equals(representation))
                .findFirst();
    }

    private OptionalDouble measure(Optional<Property> p) {
        if (p.isEmpty()) {
            return OptionalDouble.empty();
        }
        for (long i : p.get().items()) {
            Item it = item(i);
            if (it.kind().equals("measure")) {
                return it.value();
            }
        }
        return OptionalDouble.empty();
    }

    private Optional<String> description(Optional<Property> p) {
        if (p.isEmpty()) {
            return Optional.empty();
        }
        for (long i : p.get().items()) {
            Item it = item(i);
            if (it.kind().equals("text")) {
                return Optional.of(it.text());
            }
        }
        return Optional.empty();
    }

    private Optional<Long> itemOfType(Optional<Property> p, String type) {
        if (p.isEmpty()) {
            return Optional.empty();
        }
        for (long i : p.get().items()) {
            if (isA(i, type)) {
                return Optional.of(i);
            }
        }
        return Optional.empty();
    }

    /** Shape representations of a PRODUCT_DEFINITION_SHAPE or PROPERTY_DEFINITION, by both relationship kinds. */
    private List<Long> representationsOf(long definition) {
        List<Long> out = new ArrayList<>();
        for (long sdr : usersOf(definition, "SHAPE_DEFINITION_REPRESENTATION", 0)) {
            ref(rec(sdr, "SHAPE_DEFINITION_REPRESENTATION").orElseThrow().param(1))
                    .ifPresent(out::add);
        }
        for (long pdr : usersOf(definition, "PROPERTY_DEFINITION_REPRESENTATION", 0)) {
            ref(rec(pdr, "PROPERTY_DEFINITION_REPRESENTATION").orElseThrow().param(1))
                    .ifPresent(out::add);
        }
        return out;
    }

    /** Every item of every representation of every property definition (and shape) of a product or aspect. */
    private List<Long> shapeItems(long of) {
        List<Long> out = new ArrayList<>();
        List<Long> definitions = new ArrayList<>(usersOf(of, "PROPERTY_DEFINITION", 2));
        definitions.addAll(usersOf(of, "PRODUCT_DEFINITION_SHAPE", 2));
        for (long d : definitions) {
            for (long r : representationsOf(d)) {
                out.addAll(items(r));
            }
        }
        return out;
    }

    private Optional<Item> namedMeasure(List<Long> items, String... names) {
        for (String n : names) {
            for (long i : items) {
                Item it = item(i);
                if (it.kind().equals("measure") && it.name().equalsIgnoreCase(n)) {
                    return Optional.of(it);
                }
            }
        }
        return Optional.empty();
    }

    private OptionalDouble lengthOf(Optional<Item> it) {
        return it.isPresent() ? it.get().value() : OptionalDouble.empty();
    }

    // ---- geometry in mm ----

    private Transform3 mm(Transform3 t) {
        if (lengthScale == 1) {
            return t;
        }
        return new Transform3(
                t.r00(),
                t.r01(),
                t.r02(),
                t.r10(),
                t.r11(),
                t.r12(),
                t.r20(),
                t.r21(),
                t.r22(),
                t.tx() * lengthScale,
                t.ty() * lengthScale,
                t.tz() * lengthScale);
    }

    private Vec3 mm(Vec3 v) {
        return v.times(lengthScale);
    }

    private Transform3 placement(long id) throws StepParseException {
        return mm(geometry.placementOf(id));
    }

    private Optional<Transform3> plane(long id) throws StepParseException {
        Optional<Transform3> p = geometry.planeOf(id);
        return p.isPresent() ? Optional.of(mm(p.get())) : Optional.empty();
    }

    private Profile mm(Profile p) {
        if (lengthScale == 1 || !(p instanceof Profile.General g)) {
            return p;
        }
        List<Profile.Segment> segs = new ArrayList<>();
        for (Profile.Segment s : g.segments()) {
            if (s instanceof Profile.Arc a) {
                segs.add(new Profile.Arc(
                        mm(a.start()), mm(a.end()), mm(a.center()), a.radiusMm() * lengthScale, a.ccw()));
            } else {
                segs.add(new Profile.Line(mm(s.start()), mm(s.end())));
            }
        }
        return new Profile.General(g.entity(), g.placement(), g.curveEntity(), segs, g.closed());
    }

    // ---- project level ----

    StepNcProgram bind() throws StepParseException {
        for (int k = 0; k < file.size(); k++) {
            StepInstance i = file.instanceAt(k);
            for (StepRecord r : i.records()) {
                for (StepValue v : r.params()) {
                    for (long t : refs(v)) {
                        List<Long> l = users.computeIfAbsent(t, x -> new ArrayList<>(2));
                        if (l.isEmpty() || l.get(l.size() - 1) != i.id()) {
                            l.add(i.id());
                        }
                    }
                }
            }
        }
        readLengthUnit();
        List<Long> allWorkplans = new ArrayList<>();
        List<Long> allWorkingsteps = new ArrayList<>();
        List<Long> projects = new ArrayList<>();
        Set<Long> sequenced = new HashSet<>();
        Map<String, Integer> kinds = new TreeMap<>();
        for (int k = 0; k < file.size(); k++) {
            StepInstance i = file.instanceAt(k);
            String t = i.type();
            switch (t) {
                case "MACHINING_WORKPLAN" -> allWorkplans.add(i.id());
                case "MACHINING_WORKINGSTEP" -> allWorkingsteps.add(i.id());
                case "MACHINING_PROJECT" -> projects.add(i.id());
                case "MACHINING_PROCESS_SEQUENCE_RELATIONSHIP" ->
                    ref(i.record().param(3)).ifPresent(sequenced::add);
                default -> {}
            }
            kinds.merge(t, 1, Integer::sum);
        }
        String projectId = "";
        Optional<Long> mainId = Optional.empty();
        List<Workpiece> workpieces = new ArrayList<>();
        if (!projects.isEmpty()) {
            long project = projects.get(0);
            if (projects.size() > 1) {
                warnings.add(
                        "the file has " + projects.size() + " MACHINING_PROJECT instances; #" + project + " is used");
            }
            projectId = text(rec(project, "MACHINING_PROJECT").orElseThrow().param(0));
            for (long pdf : usersOf(project, "PRODUCT_DEFINITION_FORMATION", 2)) {
                for (long pd : usersOf(pdf, "PRODUCT_DEFINITION", 2)) {
                    for (long ppa : usersOf(pd, "PROCESS_PRODUCT_ASSOCIATION", 2)) {
                        Optional<Long> pdp = ref(rec(ppa, "PROCESS_PRODUCT_ASSOCIATION")
                                .orElseThrow()
                                .param(3));
                        Optional<Long> wp = pdp.flatMap(x -> rec(x, "PRODUCT_DEFINITION_PROCESS"))
                                .flatMap(r -> ref(r.param(2)));
                        if (wp.isPresent() && isA(wp.get(), "MACHINING_WORKPLAN") && mainId.isEmpty()) {
                            mainId = wp;
                        }
                    }
                    for (long r : usersOf(pd, "MACHINING_PROJECT_WORKPIECE_RELATIONSHIP", 3)) {
                        ref(rec(r, "MACHINING_PROJECT_WORKPIECE_RELATIONSHIP")
                                        .orElseThrow()
                                        .param(4))
                                .ifPresent(w -> workpieces.add(workpiece(w)));
                    }
                }
            }
        } else {
            warnings.add("the file has no MACHINING_PROJECT; the first workplan not inside another one is executed");
        }
        if (mainId.isEmpty()) {
            for (long w : allWorkplans) {
                if (!sequenced.contains(w)) {
                    mainId = Optional.of(w);
                    break;
                }
            }
        }
        Optional<Workplan> main = Optional.empty();
        if (mainId.isPresent()) {
            main = Optional.of(workplan(mainId.get(), new ArrayDeque<>(), Optional.empty()));
        } else {
            warnings.add("no MACHINING_WORKPLAN to execute");
        }
        List<MachiningWorkingstep> executed = main.map(Workplan::flatten).orElse(List.of());
        Set<Long> executedIds = new HashSet<>();
        executed.forEach(w -> executedIds.add(w.instanceId()));
        List<StepNcProgram.Skipped> skipped = new ArrayList<>(this.skipped);
        for (long wsId : allWorkingsteps) {
            if (executedIds.contains(wsId) || skipped.stream().anyMatch(s -> s.instanceId() == wsId)) {
                continue;
            }
            String id = text(rec(wsId, "MACHINING_WORKINGSTEP").orElseThrow().param(0));
            String reason = sequenced.contains(wsId)
                    ? "in a workplan that the main workplan does not run"
                    : "in no workplan's sequence (no MACHINING_PROCESS_SEQUENCE_RELATIONSHIP relates it)";
            skipped.add(new StepNcProgram.Skipped(wsId, id, reason, Optional.empty()));
        }
        spellings.add("AP238 integrated form (AIM): ARM objects read through their AIM mapping");
        List<String> allWarnings = new ArrayList<>(geometry.geometryWarnings());
        allWarnings.addAll(warnings);
        // the entity types the binding walked through are the AIM's generic resources: none is unknown in
        // the sense of the ARM binding, so only the kinds of the file are reported
        Map<String, Integer> unknown = new TreeMap<>();
        return new StepNcProgram(
                file.source(),
                file.schemas(),
                Dialect.AP238_AIM,
                file.size(),
                projectId,
                main,
                workpieces,
                executed,
                skipped,
                unknown,
                new ArrayList<>(spellings),
                allWarnings,
                file);
    }

    private final List<StepNcProgram.Skipped> skipped = new ArrayList<>();

    private Workpiece workpiece(long pd) {
        String id = rec(pd, "PRODUCT_DEFINITION").map(r -> text(r.param(0))).orElse("");
        Optional<String> material = Optional.empty();
        for (long mfu : usersOf(pd, "MAKE_FROM_USAGE_OPTION", 3)) {
            Optional<Long> other =
                    ref(rec(mfu, "MAKE_FROM_USAGE_OPTION").orElseThrow().param(4));
            if (other.isPresent()) {
                for (long md : usersOf(other.get(), "MATERIAL_DESIGNATION", 1)) {
                    material = Optional.of(
                            text(rec(md, "MATERIAL_DESIGNATION").orElseThrow().param(0)));
                }
            }
        }
        OptionalDouble tolerance = OptionalDouble.empty();
        for (long prop : usersOf(pd, "PROPERTY_DEFINITION", 2)) {
            if (text(rec(prop, "PROPERTY_DEFINITION").orElseThrow().param(0)).equalsIgnoreCase("global tolerance")) {
                for (long r : representationsOf(prop)) {
                    for (long i : items(r)) {
                        Item it = item(i);
                        if (it.kind().equals("measure")) {
                            tolerance = it.value();
                        }
                    }
                }
            }
        }
        return new Workpiece(pd, id, material, tolerance, boundingBlock(pd, id));
    }

    /**
     * The workpiece's its_bounding_geometry when it is a block (AP238 5.1.4.1.4 #1): the
     * BLOCK_SHAPE_REPRESENTATION of a PRODUCT_DEFINITION the workpiece is made from
     * (MAKE_FROM_USAGE_OPTION relating the workpiece), through that definition's
     * PRODUCT_DEFINITION_SHAPE and SHAPE_DEFINITION_REPRESENTATION, as annex J.6 writes it. A
     * bounding geometry of another kind, several, or a block that cannot be read exactly is
     * reported and left unread: without a block the stock is what the file states otherwise
     * (program check), never a guessed box. The block of a rawpiece (a workpiece the workpiece is
     * made from, which is made from a block in turn, as J.6's 'STOCK') is not this workpiece's
     * bounding geometry: it is reported and not read, since nothing states where the rawpiece
     * lies in the workpiece's frame (the ARM binder does not read its_rawpiece either).
     */
    private Optional<Workpiece.Block> boundingBlock(long pd, String id) {
        String who = "workpiece #" + pd + " '" + id + "'";
        List<Long> shapes = new ArrayList<>();
        for (long made : madeFrom(pd)) {
            shapes.addAll(madeShapes(made));
            for (long further : madeFrom(made)) {
                if (further == pd) {
                    continue;
                }
                for (long r : madeShapes(further)) {
                    if (isA(r, "BLOCK_SHAPE_REPRESENTATION")) {
                        String rawpiece = rec(made, "PRODUCT_DEFINITION")
                                .map(x -> text(x.param(0)))
                                .orElse("");
                        warnings.add(who + ": the workpiece it is made from, #" + made + " '" + rawpiece
                                + "' (its rawpiece), has a block of its own (#" + r
                                + " BLOCK_SHAPE_REPRESENTATION): not taken as this workpiece's stock, since the"
                                + " file does not state where the rawpiece lies in this workpiece's frame");
                    }
                }
            }
        }
        if (shapes.isEmpty()) {
            return Optional.empty();
        }
        if (shapes.size() > 1) {
            warnings.add(who + " has several bounding geometries ("
                    + String.join(
                            ", ",
                            shapes.stream().map(r -> "#" + r + " " + typeOf(r)).toList())
                    + "): none read, the stock is not known");
            return Optional.empty();
        }
        long r = shapes.get(0);
        if (!isA(r, "BLOCK_SHAPE_REPRESENTATION")) {
            warnings.add(who + ": its bounding geometry #" + r + " is a " + typeOf(r)
                    + ", not a BLOCK_SHAPE_REPRESENTATION: not read, the stock is not known");
            return Optional.empty();
        }
        return block(r, who + ": its bounding geometry #" + r + " BLOCK_SHAPE_REPRESENTATION");
    }

    /** The PRODUCT_DEFINITIONs a product definition is made from (MAKE_FROM_USAGE_OPTION's related). */
    private List<Long> madeFrom(long pd) {
        List<Long> out = new ArrayList<>();
        for (long mfu : usersOf(pd, "MAKE_FROM_USAGE_OPTION", 3)) {
            Optional<Long> made =
                    ref(rec(mfu, "MAKE_FROM_USAGE_OPTION").orElseThrow().param(4));
            if (made.isPresent() && made.get() != pd && isA(made.get(), "PRODUCT_DEFINITION")) {
                out.add(made.get());
            }
        }
        return out;
    }

    /** The shape representations of a product definition (its PRODUCT_DEFINITION_SHAPE's). */
    private List<Long> madeShapes(long pd) {
        List<Long> out = new ArrayList<>();
        for (long pds : usersOf(pd, "PRODUCT_DEFINITION_SHAPE", 2)) {
            out.addAll(representationsOf(pds));
        }
        return out;
    }

    /**
     * A BLOCK_SHAPE_REPRESENTATION as ISO 14649's BLOCK. Its four items (WR1-WR5): the 'orientation'
     * placement and the 'length', 'width' and 'height' length measures, each once. The placement is
     * at the centre of the block's rectangle in its x-y plane, the width along its x axis, the
     * height along y and the length along z (IP1); the rectangle is swept over the length from the
     * placement along +z, as the cylindrical_shape_representation, which stands for ISO 10303-42's
     * right_circular_cylinder (one base at its position, the height along +z), sweeps its circle.
     * The BLOCK's corner is therefore half the width and half the height back from the placement,
     * in its plane. Lengths are in their own units; the placement in the file's length unit.
     */
    private Optional<Workpiece.Block> block(long r, String what) {
        Map<String, List<Long>> named = new LinkedHashMap<>();
        for (String n : List.of("orientation", "length", "width", "height")) {
            named.put(n, new ArrayList<>());
        }
        List<String> why = new ArrayList<>();
        for (long i : items(r)) {
            String n = item(i).name().toLowerCase(Locale.ROOT);
            if (named.containsKey(n)) {
                named.get(n).add(i);
            } else {
                why.add("an item #" + i + " " + typeOf(i) + " '" + n + "' that a block has not");
            }
        }
        for (Map.Entry<String, List<Long>> e : named.entrySet()) {
            if (e.getValue().isEmpty()) {
                why.add("no '" + e.getKey() + "'");
            } else if (e.getValue().size() > 1) {
                why.add(e.getValue().size() + " items named '" + e.getKey() + "'");
            }
        }
        double[] lengths = new double[3];
        List<String> dims = List.of("width", "height", "length");
        for (int k = 0; k < 3; k++) {
            List<Long> l = named.get(dims.get(k));
            if (l.size() != 1) {
                continue;
            }
            long i = l.get(0);
            Item it = item(i);
            Optional<Long> u = rec(i, "MEASURE_WITH_UNIT").flatMap(x -> ref(x.param(1)));
            if (!isA(i, "LENGTH_MEASURE_WITH_UNIT")
                    || !isA(i, "MEASURE_REPRESENTATION_ITEM")
                    || it.value().isEmpty()) {
                why.add("its '" + dims.get(k) + "' #" + i + " is not a length measure with its unit");
            } else if (u.isEmpty() || !isA(u.get(), "LENGTH_UNIT")) {
                why.add("its '" + dims.get(k) + "' #" + i + " is not in a length unit");
            } else if (!(it.value().getAsDouble() > 0)) {
                // ISO 10303-42's block has positive_length_measures: a block of no or negative size is no stock
                why.add("its '" + dims.get(k) + "' is " + num(it.value().getAsDouble()) + " mm, not positive");
            } else {
                lengths[k] = it.value().getAsDouble();
            }
        }
        Transform3 orientation = Transform3.IDENTITY;
        List<Long> o = named.get("orientation");
        if (o.size() == 1) {
            if (!isA(o.get(0), "AXIS2_PLACEMENT_3D")) {
                why.add("its 'orientation' #" + o.get(0) + " is a " + typeOf(o.get(0)) + ", not an AXIS2_PLACEMENT_3D");
            } else {
                try {
                    orientation = placement(o.get(0));
                } catch (StepParseException ex) {
                    why.add("its 'orientation' cannot be read: " + ex.problem());
                }
            }
        }
        if (!why.isEmpty()) {
            warnings.add(what + " has " + String.join("; ", why) + ": not read, the stock is not known");
            return Optional.empty();
        }
        spellings.add("the workpiece's block: a BLOCK_SHAPE_REPRESENTATION placed at the centre of its x-y"
                + " rectangle, width along x, height along y, length along z (AP238 IP1), read as"
                + " ISO 14649's BLOCK from its corner");
        Transform3 corner = orientation.times(Transform3.translation(-lengths[0] / 2, -lengths[1] / 2, 0));
        return Optional.of(new Workpiece.Block(corner, lengths[0], lengths[1], lengths[2]));
    }

    private Optional<Setup> setupOf(long workplan) throws StepParseException {
        for (long pdp : usersOf(workplan, "PRODUCT_DEFINITION_PROCESS", 2)) {
            for (long ppa : usersOf(pdp, "PROCESS_PRODUCT_ASSOCIATION", 3)) {
                Optional<Long> pd = ref(
                        rec(ppa, "PROCESS_PRODUCT_ASSOCIATION").orElseThrow().param(2));
                if (pd.isPresent() && isSetup(pd.get())) {
                    return Optional.of(setup(pd.get()));
                }
            }
        }
        return Optional.empty();
    }

    private boolean isSetup(long pd) {
        Optional<Long> pdf = rec(pd, "PRODUCT_DEFINITION").flatMap(r -> ref(r.param(2)));
        Optional<Long> product =
                pdf.flatMap(x -> rec(x, "PRODUCT_DEFINITION_FORMATION")).flatMap(r -> ref(r.param(2)));
        return product.isPresent() && isA(product.get(), "MACHINING_SETUP");
    }

    private Setup setup(long pd) throws StepParseException {
        Optional<Long> pdf = rec(pd, "PRODUCT_DEFINITION").flatMap(r -> ref(r.param(2)));
        String id = pdf.flatMap(x -> rec(x, "PRODUCT_DEFINITION_FORMATION"))
                .flatMap(r -> ref(r.param(2)))
                .flatMap(x -> rec(x, "MACHINING_SETUP"))
                .map(r -> text(r.param(0)))
                .orElse("");
        Transform3 origin = Transform3.IDENTITY;
        Optional<Transform3> secplane = Optional.empty();
        for (long pds : usersOf(pd, "PRODUCT_DEFINITION_SHAPE", 2)) {
            for (long r : representationsOf(pds)) {
                for (long i : items(r)) {
                    if (isA(i, "AXIS2_PLACEMENT_3D")) {
                        origin = placement(i);
                    }
                }
            }
        }
        for (long prop : usersOf(pd, "PROPERTY_DEFINITION", 2)) {
            if (text(rec(prop, "PROPERTY_DEFINITION").orElseThrow().param(0)).equalsIgnoreCase("security plane")) {
                for (long r : representationsOf(prop)) {
                    for (long i : items(r)) {
                        if (isA(i, "PLANE")) {
                            secplane = plane(i);
                        }
                    }
                }
            }
        }
        List<Setup.WorkpieceSetup> wps = new ArrayList<>();
        for (long msw : usersOf(pd, "MACHINING_SETUP_WORKPIECE_RELATIONSHIP", 3)) {
            long wp = ref(rec(msw, "MACHINING_SETUP_WORKPIECE_RELATIONSHIP")
                            .orElseThrow()
                            .param(4))
                    .orElse(0L);
            Transform3 o = Transform3.IDENTITY;
            for (long pds : usersOf(msw, "PRODUCT_DEFINITION_SHAPE", 2)) {
                for (long cdsr : usersOf(pds, "CONTEXT_DEPENDENT_SHAPE_REPRESENTATION", 1)) {
                    Optional<Long> rr = ref(rec(cdsr, "CONTEXT_DEPENDENT_SHAPE_REPRESENTATION")
                            .orElseThrow()
                            .param(0));
                    Optional<Long> idt = rr.flatMap(x -> rec(x, "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION"))
                            .flatMap(r -> ref(r.param(0)));
                    Optional<Long> to = idt.flatMap(x -> rec(x, "ITEM_DEFINED_TRANSFORMATION"))
                            .flatMap(r -> ref(r.param(3)));
                    if (to.isPresent() && isA(to.get(), "AXIS2_PLACEMENT_3D")) {
                        o = placement(to.get());
                    }
                }
            }
            wps.add(new Setup.WorkpieceSetup(wp, o));
        }
        return new Setup(pd, id, origin, secplane, wps);
    }

    private Workplan workplan(long w, Deque<Long> stack, Optional<Setup> inherited) throws StepParseException {
        if (stack.contains(w)) {
            throw error(w, "workplan contains itself (through " + stack + ")");
        }
        if (stack.size() >= Iso14649Binder.MAX_WORKPLAN_NESTING) {
            throw error(w, "workplans are nested more than " + Iso14649Binder.MAX_WORKPLAN_NESTING + " deep");
        }
        stack.push(w);
        Optional<Setup> own = setupOf(w);
        Optional<Setup> effective = own.isPresent() ? own : inherited;
        List<long[]> order = new ArrayList<>();
        List<Double> positions = new ArrayList<>();
        for (long rel : usersOf(w, "MACHINING_PROCESS_SEQUENCE_RELATIONSHIP", 2)) {
            StepRecord r = rec(rel, "MACHINING_PROCESS_SEQUENCE_RELATIONSHIP").orElseThrow();
            Optional<Long> el = ref(r.param(3));
            if (el.isPresent()) {
                order.add(new long[] {el.get(), order.size()});
                positions.add(number(r.param(4)).orElse(Double.MAX_VALUE));
            }
        }
        List<Integer> idx = new ArrayList<>();
        for (int i = 0; i < order.size(); i++) {
            idx.add(i);
        }
        // sequence_position orders the elements; equal or missing positions keep the file's order
        idx.sort(Comparator.comparingDouble((Integer i) -> positions.get(i)).thenComparingInt(i -> i));
        List<Executable> elements = new ArrayList<>();
        for (int i : idx) {
            long id = order.get(i)[0];
            if (isA(id, "MACHINING_WORKPLAN")) {
                elements.add(workplan(id, stack, effective));
            } else if (isA(id, "MACHINING_WORKINGSTEP")) {
                Optional<MachiningWorkingstep> ws = workingstep(id, effective);
                if (ws.isPresent()) {
                    elements.add(ws.get());
                }
            } else {
                StepInstance x = inst(id);
                String name = x != null && !x.isComplex() ? text(x.record().param(0)) : "";
                elements.add(new Executable.Other(id, name, typeOf(id)));
            }
        }
        stack.pop();
        String id = text(rec(w, "MACHINING_WORKPLAN").orElseThrow().param(0));
        return new Workplan(w, id, elements, own);
    }

    /** The workingstep, or empty (with a skipped entry naming why) when it has no feature or operation. */
    private Optional<MachiningWorkingstep> workingstep(long ws, Optional<Setup> setup) throws StepParseException {
        MachiningWorkingstep done = workingsteps.get(ws);
        if (done != null) {
            return Optional.of(done);
        }
        String id = text(rec(ws, "MACHINING_WORKINGSTEP").orElseThrow().param(0));
        Optional<Long> op = firstUser(ws, "MACHINING_OPERATION_RELATIONSHIP", 2)
                .flatMap(r -> ref(
                        rec(r, "MACHINING_OPERATION_RELATIONSHIP").orElseThrow().param(3)));
        Optional<Long> feature = Optional.empty();
        for (long mfr : usersOf(ws, "MACHINING_FEATURE_RELATIONSHIP", 2)) {
            Optional<Long> process =
                    ref(rec(mfr, "MACHINING_FEATURE_RELATIONSHIP").orElseThrow().param(3));
            if (process.isEmpty()) {
                continue;
            }
            for (long pp : usersOf(process.get(), "PROPERTY_PROCESS", 2)) {
                for (long ppa : usersOf(pp, "PROCESS_PROPERTY_ASSOCIATION", 2)) {
                    Optional<Long> f = ref(rec(ppa, "PROCESS_PROPERTY_ASSOCIATION")
                            .orElseThrow()
                            .param(3));
                    if (f.isPresent() && feature.isEmpty()) {
                        feature = f;
                    }
                }
            }
        }
        if (op.isEmpty() || feature.isEmpty()) {
            skipped.add(new StepNcProgram.Skipped(
                    ws,
                    id,
                    "the workingstep has no "
                            + (op.isEmpty()
                                    ? "operation (MACHINING_OPERATION_RELATIONSHIP)"
                                    : "feature (MACHINING_FEATURE_RELATIONSHIP to a PROCESS_PROPERTY_ASSOCIATION)"),
                    Optional.empty()));
            return Optional.empty();
        }
        List<Property> props = actionProperties(ws);
        Optional<Transform3> secplane = Optional.empty();
        Optional<Long> sp = itemOfType(property(props, "security plane"), "PLANE");
        if (sp.isPresent()) {
            secplane = plane(sp.get());
        }
        Feature f = feature(feature.get(), secplane);
        Operation o = operation(op.get());
        Transform3 wpToSetup = Transform3.IDENTITY;
        if (setup.isPresent()) {
            long wp = rec(feature.get(), "SHAPE_ASPECT")
                    .flatMap(r -> ref(r.param(2)))
                    .flatMap(pds -> rec(pds, "PRODUCT_DEFINITION_SHAPE"))
                    .flatMap(r -> ref(r.param(2)))
                    .orElse(0L);
            for (Setup.WorkpieceSetup w : setup.get().workpieceSetups()) {
                if (wp == 0 || wp == w.workpieceInstanceId()) {
                    wpToSetup = w.origin();
                    break;
                }
            }
        }
        MachiningWorkingstep out = new MachiningWorkingstep(ws, id, secplane, f, o, setup, wpToSetup);
        workingsteps.put(ws, out);
        return Optional.of(out);
    }

    // ---- features ----

    private Feature feature(long id, Optional<Transform3> securityPlane) throws StepParseException {
        Feature done = features.get(id);
        if (done != null) {
            return done;
        }
        StepInstance fi = inst(id);
        String entity = "?";
        String featureId = "";
        if (fi != null) {
            for (StepRecord r : fi.records()) {
                if (!FEATURE_NOISE.contains(r.type())) {
                    entity = r.type();
                }
            }
            featureId = fi.part("SHAPE_ASPECT").map(r -> text(r.param(0))).orElse("");
            if (!fi.isComplex() && fi.record().type().equals("INSTANCED_FEATURE")) {
                // a feature of no shape, e.g. the toolpath feature of explicit toolpaths (description 'toolpath')
                String kind = text(fi.record().param(1))
                        .trim()
                        .toUpperCase(Locale.ROOT)
                        .replace(' ', '_');
                entity = kind.isEmpty() ? "INSTANCED_FEATURE" : kind + "_FEATURE";
                featureId = text(fi.record().param(0));
            }
        }
        Optional<Long> pds = firstUser(id, "PRODUCT_DEFINITION_SHAPE", 2);
        Transform3 placement = Transform3.IDENTITY;
        Optional<Long> placementId = Optional.empty();
        Optional<Transform3> depthPlane = Optional.empty();
        List<Long> measures = new ArrayList<>();
        Map<String, Long> components = new LinkedHashMap<>();
        List<EndUse> endUses = new ArrayList<>();
        if (pds.isPresent()) {
            for (long r : representationsOf(pds.get())) {
                String repName = inst(r) == null ? "" : text(inst(r).record().param(0));
                for (long i : items(r)) {
                    if (isA(i, "AXIS2_PLACEMENT_3D") && placementId.isEmpty()) {
                        placementId = Optional.of(i);
                        placement = placement(i);
                    } else if (isA(i, "PLANE") && repName.equalsIgnoreCase("maximum feature limit")) {
                        depthPlane = plane(i);
                    } else {
                        measures.add(i);
                    }
                }
            }
            for (long aspect : usersOf(pds.get(), "SHAPE_ASPECT", 2)) {
                String occurrence = text(rec(aspect, "SHAPE_ASPECT")
                                .orElseThrow()
                                .param(1))
                        .toLowerCase(Locale.ROOT)
                        .replace(" occurrence", "")
                        .trim();
                for (String relType : List.of("SHAPE_DEFINING_RELATIONSHIP", "FEATURE_COMPONENT_RELATIONSHIP")) {
                    for (long rel : usersOf(aspect, relType, 3)) {
                        StepRecord r = rec(rel, relType).orElseThrow();
                        Optional<Long> c = ref(r.param(2));
                        if (c.isEmpty()) {
                            continue;
                        }
                        components.putIfAbsent(occurrence, c.get());
                        if (occurrence.equals("end condition")) {
                            // a slot has two end condition occurrences (one for a loop): each is told
                            // apart by its relationship's name, not by the aspect
                            endUses.add(new EndUse(text(r.param(0)), c.get(), rel));
                        }
                    }
                }
            }
        }
        Optional<Long> boundary = first(
                components,
                "removal boundary",
                "boundary",
                "feature boundary",
                "swept shape",
                "wall boundary",
                "its boundary",
                "open boundary");
        Optional<Profile> profile = Optional.empty();
        if (boundary.isPresent()) {
            profile = Optional.of(profile(boundary.get(), placementId));
        }
        Feature.FeatureType type = switch (entity) {
            case "FLAT_FACE", "PLANAR_FACE" -> Feature.FeatureType.PLANAR_FACE;
            case "ROUND_HOLE" -> Feature.FeatureType.ROUND_HOLE;
            case "POCKET", "CLOSED_POCKET" ->
                profile.isPresent() && isOpen(profile.get())
                        ? Feature.FeatureType.OPEN_POCKET
                        : Feature.FeatureType.CLOSED_POCKET;
            case "SLOT" -> Feature.FeatureType.SLOT;
            case "STEP" -> Feature.FeatureType.STEP;
            case "BOSS" -> Feature.FeatureType.BOSS;
            case "OUTSIDE_PROFILE", "GENERAL_OUTSIDE_PROFILE" -> Feature.FeatureType.GENERAL_OUTSIDE_PROFILE;
            default -> Feature.FeatureType.OTHER;
        };
        // ISO 10303-113 pocket WR16, step WR5, flat_face WR6: the material the feature leaves
        // standing is its 'uncut volume', each BOSS related to it; the bosses are read as the ARM's
        // its_boss. A boss that cannot be read leaves the feature refused: milled without it, the
        // boss would be cut away
        List<Feature> bosses = new ArrayList<>();
        List<String> unread = new ArrayList<>();
        for (long b : pds.isPresent() ? uncutVolumes(pds.get()) : List.<Long>of()) {
            List<String> why = new ArrayList<>();
            Optional<Feature> boss = boss(b, why);
            if (boss.isPresent()) {
                bosses.add(boss.get());
            } else {
                String kind = isA(b, "BOSS") ? "BOSS" : isA(b, "PROTRUSION") ? "PROTRUSION" : typeOf(b);
                unread.add(kind + " #" + b + " (" + String.join("; ", why) + ")");
            }
        }
        if (!unread.isEmpty()) {
            String reason = " around an 'uncut volume' the AIM binder cannot read: " + String.join(", ", unread)
                    + ": milled without it, the boss would be cut away";
            bosses.clear();
            if (profile.isPresent()) {
                profile = Optional.of(new Profile.Other(
                        profile.get().entity() + reason, profile.get().placement(), boundary.orElse(id)));
            } else {
                // a feature without an outline (a hole) is refused by its kind
                entity = entity + reason;
                type = Feature.FeatureType.OTHER;
            }
        }
        if (securityPlane.isPresent()
                && type != Feature.FeatureType.OTHER
                && placement.zAxis().dot(securityPlane.get().zAxis()) < -0.999) {
            // ISO 14649-10: the feature's z axis points out of the material, towards the tool; a
            // feature reached from a security plane facing the other way has its axis written
            // upside down (Annex J.6 gives the pocket the direction of its depth path, the ARM
            // example +z): the axis is reversed, the reference direction kept
            placement = Transform3.ofFrame(
                    placement.translationPart(), placement.zAxis().times(-1), placement.xAxis());
            warnings.add("#" + id + " " + entity + " '" + featureId + "': its placement's axis points away from its"
                    + " workingstep's security plane (into the material); read reversed");
        }
        Optional<Long> placementOfFeature = placementId;
        Optional<TravelPath> travel =
                first(components, "course of travel", "path").map(c -> travel(c, placementOfFeature));
        OptionalDouble diameter = OptionalDouble.empty();
        Optional<Long> dia = first(components, "diameter");
        if (dia.isPresent()) {
            diameter = lengthOf(namedMeasure(shapeItems(dia.get()), "diameter"));
            if (diameter.isEmpty()) {
                Profile p = profile(dia.get(), placementId);
                if (p instanceof Profile.Circular c) {
                    diameter = OptionalDouble.of(c.diameterMm());
                }
            }
        }
        Optional<String> bottom = first(components, "bottom condition").map(this::bottomCondition);
        OptionalDouble depth = depthPlane.isPresent()
                ? OptionalDouble.of(-depthPlane.get().translationPart().z() + 0.0)
                : OptionalDouble.empty();
        if (depth.isEmpty()) {
            // a depth given as the feature's path (hole depth, pocket depth) when there is no depth plane
            Optional<Long> path = first(components, "hole depth", "pocket depth", "depth");
            if (path.isPresent()) {
                depth = travel(path.get(), placementId).distanceMm();
            }
        }
        List<Feature.SlotEnd> ends = List.of();
        if (type == Feature.FeatureType.SLOT) {
            ends = slotEnds(endUses);
            if (boundary.isPresent() && profile.isPresent()) {
                // AP238 5.2.2.3.5: the depth of the open profile gives the slot's depth (square-U,
                // rounded-U and tee profiles carry it as 'depth'); the ARM's is the depth plane's
                OptionalDouble profileDepth = lengthOf(namedMeasure(shapeItems(boundary.get()), "depth"));
                if (profileDepth.isPresent() && depth.isEmpty()) {
                    depth = profileDepth;
                } else if (profileDepth.isPresent()
                        && Math.abs(profileDepth.getAsDouble() - depth.getAsDouble()) > SAME_DEPTH_MM) {
                    profile = Optional.of(new Profile.Other(
                            profile.get().entity() + " " + num(profileDepth.getAsDouble()) + " mm deep in a slot "
                                    + num(depth.getAsDouble()) + " mm deep (its maximum feature limit)",
                            profile.get().placement(),
                            boundary.get()));
                }
            }
        }
        OptionalDouble planar = lengthOf(namedMeasure(measures, "fillet radius", "planar radius", "base radius"));
        OptionalDouble orthogonal = lengthOf(namedMeasure(measures, "orthogonal fillet radius", "orthogonal radius"));
        OptionalDouble slope = lengthOf(namedMeasure(measures, "slope"));
        if (slope.isPresent() && Math.abs(slope.getAsDouble()) > 1e-9 && profile.isPresent()) {
            // walls milled upright would cut a drafted pocket's away below its top (as in the ARM)
            profile = Optional.of(new Profile.Other(
                    profile.get().entity() + " with walls sloping "
                            + String.format(java.util.Locale.ROOT, "%.6g", slope.getAsDouble())
                                    .replaceAll("\\.?0+$", "")
                            + " deg from upright (slope)",
                    profile.get().placement(),
                    id));
        }
        Feature out = new Feature(
                id,
                type,
                entity,
                featureId,
                placement,
                depth,
                depthPlane,
                profile,
                travel,
                diameter,
                bottom,
                planar,
                orthogonal,
                List.of(),
                ends,
                bosses,
                taper(components));
        features.put(id, out);
        return out;
    }

    /**
     * The shape aspects related to a feature's 'uncut volume' (a COMPOSITE_SHAPE_ASPECT, or a
     * SHAPE_ASPECT, of that name) by a FEATURE_COMPONENT_RELATIONSHIP or another
     * SHAPE_ASPECT_RELATIONSHIP, the uncut volume relating, each a BOSS or a PROTRUSION (pocket
     * WR16, step WR5, flat_face WR6). An 'uncut volume' that relates nothing is given as itself,
     * which is no boss: material stands there whose shape the file does not give.
     */
    private List<Long> uncutVolumes(long pds) {
        List<Long> out = new ArrayList<>();
        for (String aspectType : List.of("COMPOSITE_SHAPE_ASPECT", "SHAPE_ASPECT")) {
            for (long a : usersOf(pds, aspectType, 2)) {
                if (!text(rec(a, aspectType).orElseThrow().param(0)).trim().equalsIgnoreCase("uncut volume")) {
                    continue;
                }
                int before = out.size();
                for (String relType : List.of("FEATURE_COMPONENT_RELATIONSHIP", "SHAPE_ASPECT_RELATIONSHIP")) {
                    for (long rel : usersOf(a, relType, 2)) {
                        ref(rec(rel, relType).orElseThrow().param(3))
                                .filter(b -> !out.contains(b))
                                .ifPresent(out::add);
                    }
                }
                if (out.size() == before && !out.contains(a)) {
                    out.add(a);
                }
            }
        }
        return out;
    }

    /** What a boss's profile occurrence is named and the profiles it may relate, by the boss's description. */
    private static final Map<String, List<String>> BOSS_PROFILES = Map.of(
            "circular", List.of("circular profile", "CIRCULAR_CLOSED_PROFILE"),
            "rectangular", List.of("rectangular profile", "RECTANGULAR_CLOSED_PROFILE"),
            "complex", List.of("enclosed boundary", "CLOSED_PATH_PROFILE", "NGON_CLOSED_PROFILE"));

    /** A boss's top lies at its placement, and its height and top along its axis, within this (mm, and cosine). */
    static final double BOSS_TOP_MM = 1e-6;

    /**
     * A BOSS of an 'uncut volume' as the ARM binder gives an its_boss: placed by its
     * 'orientation' (at its top, as the ARM's feature_placement), as deep as its 'boss height', its
     * boundary the closed profile its description names, or empty with why it cannot be read in
     * {@code why}. ISO 10303-113 boss: WR1 (description 'circular', 'rectangular' or 'complex'),
     * WR2 ('boss height occurrence', a 'linear' PATH_FEATURE_COMPONENT related as 'boss height'),
     * WR4, WR5 (its parameters: 'orientation' and an optional 'fillet radius'), WR6, WR9, WR11 (the
     * profile: 'circular profile occurrence' a CIRCULAR_CLOSED_PROFILE, 'enclosed boundary
     * occurrence' a CLOSED_PATH_PROFILE or NGON_CLOSED_PROFILE, 'rectangular profile occurrence' a
     * RECTANGULAR_CLOSED_PROFILE, each 'profile usage'), WR7 ('top condition occurrence' related to
     * a BOSS_TOP as 'boss top usage'; boss_top WR2-WR4, WR6, WR9: 'planar', its location and
     * direction, named 'boss height start' or 'boss height end', an optional 'top radius'), WR8,
     * WR10 (a taper), WR12 (an optional maximum feature limit). What ISO 14649-10's BOSS cannot
     * hold (a fillet at its foot, a rounded top, a taper, corner radii, a top away from its
     * placement or not square to its axis) is not read: milled as a plain upright boss it would
     * not be the boss drawn.
     */
    private Optional<Feature> boss(long id, List<String> why) throws StepParseException {
        if (!isA(id, "BOSS")) {
            why.add(
                    isA(id, "PROTRUSION")
                            ? "a PROTRUSION, whose shape the binder does not read"
                            : isA(id, "COMPOSITE_SHAPE_ASPECT")
                                            || isA(id, "SHAPE_ASPECT") && !isA(id, "FEATURE_DEFINITION")
                                    ? "an 'uncut volume' relating no BOSS"
                                    : "not a BOSS nor a PROTRUSION");
            return Optional.empty();
        }
        String bossId = rec(id, "SHAPE_ASPECT").map(r -> text(r.param(0))).orElse("");
        String kind = rec(id, "CHARACTERIZED_OBJECT")
                .map(r -> text(r.param(1)).trim().toLowerCase(Locale.ROOT))
                .orElse("");
        List<String> profileKinds = BOSS_PROFILES.get(kind);
        if (profileKinds == null) {
            why.add("'" + bossId + "' described '" + kind
                    + "', not 'circular', 'rectangular' nor 'complex' (boss WR1)");
            return Optional.empty();
        }
        Optional<Long> pds = firstUser(id, "PRODUCT_DEFINITION_SHAPE", 2);
        if (pds.isEmpty()) {
            why.add("'" + bossId + "' has no shape (PRODUCT_DEFINITION_SHAPE)");
            return Optional.empty();
        }
        Optional<Long> placementId = Optional.empty();
        Optional<Transform3> limit = Optional.empty();
        for (long r : representationsOf(pds.get())) {
            String repName = inst(r) == null ? "" : text(inst(r).record().param(0));
            for (long i : items(r)) {
                if (repName.equalsIgnoreCase("maximum feature limit") && isA(i, "PLANE")) {
                    limit = plane(i);
                } else if (isA(i, "AXIS2_PLACEMENT_3D") && placementId.isEmpty()) {
                    placementId = Optional.of(i);
                } else if (item(i).name().trim().equalsIgnoreCase("fillet radius")
                        && item(i).kind().equals("measure")
                        && item(i).value().orElse(-1) == 0) {
                    continue;
                } else {
                    why.add("'" + bossId + "' has "
                            + (item(i).name().isBlank()
                                    ? "a " + typeOf(i)
                                    : "'" + item(i).name() + "' "
                                            + item(i).value().stream()
                                                    .mapToObj(v -> num(v) + " mm")
                                                    .findFirst()
                                                    .orElse(""))
                            + " among its parameters ('orientation' and a 'fillet radius' at its foot, boss WR4),"
                            + " which ISO 14649-10's boss has not");
                }
            }
        }
        if (placementId.isEmpty()) {
            why.add("'" + bossId + "' has no placement ('orientation')");
        }
        // the aspects of the boss by occurrence, each with the relationships that relate a component to it
        Map<String, List<Long>> aspects = new LinkedHashMap<>();
        for (long aspect : usersOf(pds.get(), "SHAPE_ASPECT", 2)) {
            String occurrence = text(rec(aspect, "SHAPE_ASPECT").orElseThrow().param(1))
                    .toLowerCase(Locale.ROOT)
                    .replace(" occurrence", "")
                    .trim();
            List<Long> rels = aspects.computeIfAbsent(occurrence, k -> new ArrayList<>());
            for (String relType : List.of("SHAPE_DEFINING_RELATIONSHIP", "FEATURE_COMPONENT_RELATIONSHIP")) {
                rels.addAll(usersOf(aspect, relType, 3));
            }
        }
        for (String occurrence : aspects.keySet()) {
            if (!List.of("boss height", profileKinds.get(0), "top condition").contains(occurrence)) {
                why.add("'" + bossId + "' has a '" + occurrence + " occurrence'"
                        + (occurrence.startsWith("change in") ? " (a taper, boss WR8, WR10)" : "")
                        + ", which ISO 14649-10's boss has not");
            }
        }
        Transform3 placement = Transform3.IDENTITY;
        if (placementId.isPresent()) {
            placement = placement(placementId.get());
        }
        // boss WR2: its height, a 'linear' path along its axis
        List<Long> heights = related(aspects, "boss height", "boss height", "PATH_FEATURE_COMPONENT");
        OptionalDouble height = OptionalDouble.empty();
        if (heights.size() != 1) {
            why.add("'" + bossId + "' has " + heights.size() + " 'boss height's, not one (a 'linear'"
                    + " PATH_FEATURE_COMPONENT related to its 'boss height occurrence', boss WR2)");
        } else {
            TravelPath h = travel(heights.get(0), placementId);
            if (!h.entity().equals("LINEAR_PATH")) {
                why.add("'" + bossId + "' has a 'boss height' " + h.entity() + ", not a 'linear' path (boss WR2)");
            } else if (h.distanceMm().isEmpty() || !(h.distanceMm().getAsDouble() > 0)) {
                why.add("'" + bossId + "' has a 'boss height' without a positive 'distance'");
            } else if (h.direction().isPresent()
                    && Math.abs(h.placement()
                                    .applyToDirection(h.direction().get())
                                    .normalized()
                                    .z())
                            < 1 - BOSS_TOP_MM) {
                why.add("'" + bossId + "' has a 'boss height' at an angle to its axis");
            } else {
                height = h.distanceMm();
            }
        }
        Optional<Transform3> depthPlane = Optional.empty();
        if (limit.isPresent() && height.isPresent()) {
            double limitDepth = -limit.get().translationPart().z() + 0.0;
            if (Math.abs(limitDepth - height.getAsDouble()) > SAME_DEPTH_MM) {
                why.add("'" + bossId + "' is " + num(height.getAsDouble()) + " mm high and its maximum feature limit "
                        + num(limitDepth) + " mm below its top");
            } else {
                depthPlane = limit;
            }
        }
        // boss WR6, WR9, WR11: the closed profile its description names
        List<Long> profiles = related(
                aspects,
                profileKinds.get(0),
                null,
                profileKinds.subList(1, profileKinds.size()).toArray(String[]::new));
        Optional<Profile> boundary = Optional.empty();
        if (profiles.size() != 1) {
            why.add("'" + bossId + "' (" + kind + ") has " + profiles.size() + " "
                    + String.join(" or ", profileKinds.subList(1, profileKinds.size())) + "s related to a '"
                    + profileKinds.get(0)
                    + " occurrence', not one");
        } else {
            boundary = bossProfile(profiles.get(0), placementId, bossId, why);
        }
        // boss WR7, boss_top: its planar top, at its placement and square to its axis
        List<Long> tops = related(aspects, "top condition", null, "BOSS_TOP");
        if (tops.size() != 1) {
            why.add("'" + bossId + "' has " + tops.size() + " BOSS_TOPs related to a 'top condition occurrence',"
                    + " not one (boss WR7)");
        } else {
            bossTop(tops.get(0), aspects.get("top condition"), placement, bossId, why);
        }
        if (!why.isEmpty()) {
            return Optional.empty();
        }
        return Optional.of(new Feature(
                id,
                Feature.FeatureType.BOSS,
                "BOSS",
                bossId,
                placement,
                height,
                depthPlane,
                boundary,
                Optional.empty(),
                OptionalDouble.empty(),
                Optional.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                List.of(),
                List.of(),
                List.of(),
                Optional.empty()));
    }

    /**
     * A round hole's change in diameter: the AIM binder does not read its shape, so a hole that
     * has one is bound with a taper of unknown size, which the planner refuses (drilled straight,
     * a hole narrowing to its bottom would have its wall cut away).
     */
    private static Optional<Feature.HoleTaper> taper(Map<String, Long> components) {
        return components.keySet().stream()
                .filter(k -> k.contains("taper") || k.contains("change in diameter"))
                .findFirst()
                .map(k -> new Feature.HoleTaper(
                        "'" + k + "' (not read by the AIM binder)", OptionalDouble.empty(), OptionalDouble.empty()));
    }

    /**
     * The components of the given entities that relationships of the occurrence relate to it
     * (their relating aspect), those of the name when one is given.
     */
    private List<Long> related(Map<String, List<Long>> aspects, String occurrence, String name, String... types) {
        List<Long> out = new ArrayList<>();
        for (long rel : aspects.getOrDefault(occurrence, List.of())) {
            StepRecord r = inst(rel).record();
            if (name != null && !text(r.param(0)).trim().equalsIgnoreCase(name)) {
                continue;
            }
            Optional<Long> c = ref(r.param(2));
            if (c.isPresent() && List.of(types).stream().anyMatch(t -> isA(c.get(), t)) && !out.contains(c.get())) {
                out.add(c.get());
            }
        }
        return out;
    }

    /**
     * A boss's boundary as ISO 14649-10 has it: a circle of its 'diameter', a rectangle of its
     * 'width' and 'length' (without a 'corner radius'), a closed curve; an NGON_CLOSED_PROFILE is
     * not read.
     */
    private Optional<Profile> bossProfile(long id, Optional<Long> bossPlacement, String bossId, List<String> why)
            throws StepParseException {
        String entity = typeOf(id);
        List<String> allowed = switch (entity) {
            case "CIRCULAR_CLOSED_PROFILE" -> List.of("diameter");
            case "RECTANGULAR_CLOSED_PROFILE" -> List.of("width", "length");
            case "CLOSED_PATH_PROFILE" -> List.of();
            default -> null;
        };
        if (allowed == null) {
            why.add("'" + bossId + "' is bounded by a " + entity + ", which the AIM binder does not read");
            return Optional.empty();
        }
        List<Long> items = shapeItems(id);
        List<String> foreign = foreignItems(
                items.stream()
                        .filter(i -> !isA(i, "AXIS2_PLACEMENT_3D")
                                && !isA(i, "POLYLINE")
                                && !isA(i, "COMPOSITE_CURVE")
                                && !isA(i, "TRIMMED_CURVE"))
                        .toList(),
                allowed);
        if (!foreign.isEmpty()) {
            why.add("'" + bossId + "' is bounded by a " + entity + " with " + String.join(", ", foreign)
                    + ", which ISO 14649-10's profile has not");
            return Optional.empty();
        }
        for (String n : allowed) {
            OptionalDouble v = lengthOf(namedMeasure(items, n));
            if (v.isEmpty() || !(v.getAsDouble() > 0)) {
                why.add("'" + bossId + "' is bounded by a " + entity + " without a positive '" + n + "'");
                return Optional.empty();
            }
        }
        Profile p = profile(id, bossPlacement);
        if (p instanceof Profile.General g && (!g.closed() || g.segments().isEmpty())) {
            why.add("'" + bossId + "' is bounded by a " + entity + " without a closed curve ('profile shape')");
            return Optional.empty();
        }
        return Optional.of(p);
    }

    /**
     * Checks a boss's BOSS_TOP: 'planar', related as 'boss height start' or 'boss height end'
     * (boss_top WR6), its location on the plane through the boss's placement square to its axis,
     * its direction along that axis, no 'top radius' but 0. The top is where the ARM's
     * feature_placement puts it; a boss placed elsewhere is not read.
     */
    private void bossTop(long top, List<Long> relationships, Transform3 placement, String bossId, List<String> why)
            throws StepParseException {
        String kind = text(inst(top).record().param(1)).trim().toLowerCase(Locale.ROOT);
        if (!kind.equals("planar")) {
            why.add("'" + bossId + "' has a '" + kind + "' top, which the binder does not read: only a 'planar' one");
            return;
        }
        for (long rel : relationships) {
            StepRecord r = inst(rel).record();
            String name = text(r.param(0)).trim().toLowerCase(Locale.ROOT);
            if (ref(r.param(2)).orElse(-1L) == top
                    && !(name.equals("boss height start") || name.equals("boss height end"))) {
                why.add("'" + bossId + "' relates its top as '" + name
                        + "', not 'boss height start' nor 'boss height end' (boss_top WR6)");
            }
        }
        Optional<Vec3> location = Optional.empty();
        Optional<Vec3> direction = Optional.empty();
        for (long i : shapeItems(top)) {
            if (isA(i, "CARTESIAN_POINT")) {
                location = Optional.of(mm(geometry.pointOf(i)));
            } else if (isA(i, "DIRECTION")) {
                direction = Optional.of(geometry.directionOf(i));
            } else if (item(i).name().trim().equalsIgnoreCase("top radius")
                    && item(i).value().orElse(-1) != 0) {
                why.add("'" + bossId + "' has a 'top radius', which ISO 14649-10's boss has not");
            }
        }
        if (location.isEmpty() || direction.isEmpty()) {
            why.add("'" + bossId + "''s planar top has no " + (location.isEmpty() ? "location" : "direction")
                    + " (boss_top WR3, WR4)");
            return;
        }
        double above = location.get().minus(placement.translationPart()).dot(placement.zAxis());
        if (Math.abs(above) > BOSS_TOP_MM) {
            why.add("'" + bossId + "''s top is " + num(above) + " mm from its placement along its axis: the binder"
                    + " reads a boss placed at its top, as ISO 14649-10's");
        }
        if (Math.abs(direction.get().normalized().dot(placement.zAxis())) < 1 - BOSS_TOP_MM) {
            why.add("'" + bossId + "''s top is not square to its axis");
        }
    }

    /** A SLOT_END as its slot relates it: the relationship's name, the end, the relationship. */
    private record EndUse(String name, long end, long relationship) {}

    /**
     * A slot's ends, the course of travel's start then its end, as the ARM's end_conditions: the
     * slot's 'end condition occurrence' aspects, each related to a SLOT_END by a
     * FEATURE_COMPONENT_RELATIONSHIP ('slot end usage') named 'course of travel start' or 'course
     * of travel end' (ISO 10303-113 slot WR4, slot_end WR10); a loop has one, standing for both
     * ends of the closed course. Whatever cannot be placed at one end or read is an end of kind
     * OTHER naming why, which the planner refuses: an end read as square that is not would cut the
     * corners the part keeps.
     */
    private List<Feature.SlotEnd> slotEnds(List<EndUse> uses) {
        if (uses.size() == 1 && slotEndKind(uses.get(0).end()).equals("loop")) {
            Feature.SlotEnd loop = slotEnd(uses.get(0).end());
            return List.of(loop, loop);
        }
        Feature.SlotEnd[] at = new Feature.SlotEnd[2];
        String[] names = {"course of travel start", "course of travel end"};
        for (EndUse u : uses) {
            String name = u.name().trim().toLowerCase(Locale.ROOT);
            int k = name.equals(names[0]) ? 0 : name.equals(names[1]) ? 1 : -1;
            if (k < 0) {
                Feature.SlotEnd unplaced = unreadEnd("#" + u.end() + " " + typeOf(u.end()) + " related by #"
                        + u.relationship() + " as '" + u.name() + "', neither '" + names[0] + "' nor '" + names[1]
                        + "': which end it is is not known");
                return List.of(unplaced, unplaced);
            }
            if (at[k] != null) {
                Feature.SlotEnd twice = unreadEnd("two SLOT_ENDs related as '" + names[k] + "' (#" + u.end() + ")");
                return List.of(twice, twice);
            }
            at[k] = slotEnd(u.end());
        }
        List<Feature.SlotEnd> out = new ArrayList<>();
        for (int k = 0; k < 2; k++) {
            out.add(
                    at[k] != null
                            ? at[k]
                            : unreadEnd("none given: the slot relates no SLOT_END as '" + names[k] + "'"));
        }
        return out;
    }

    private String slotEndKind(long id) {
        return rec(id, "SLOT_END")
                .map(r -> text(r.param(1)).trim().toLowerCase(Locale.ROOT))
                .orElse("");
    }

    private static Feature.SlotEnd unreadEnd(String why) {
        return new Feature.SlotEnd(Feature.SlotEnd.EndType.OTHER, why, OptionalDouble.empty(), OptionalDouble.empty());
    }

    /**
     * One SLOT_END as the ARM's slot_end_type: its description says which (ISO 10303-113 slot_end
     * WR2), a flat end's corner radii are its 'first radius' and 'second radius' (corner_radius1
     * and corner_radius2, WR5-WR7, both optional in the ARM), a woodruff end's radius its 'radius'
     * (WR8, WR9); open, radiused and loop ends have no parameters (WR3). A measure of another name,
     * a woodruff end without its radius, or another description is not read: the end is OTHER.
     */
    private Feature.SlotEnd slotEnd(long id) {
        if (!isA(id, "SLOT_END")) {
            return unreadEnd("#" + id + " " + typeOf(id) + " (a slot's end condition should be a SLOT_END)");
        }
        String kind = slotEndKind(id);
        Feature.SlotEnd.EndType type;
        String entity;
        List<String> allowed;
        switch (kind) {
            case "open" -> {
                type = Feature.SlotEnd.EndType.OPEN;
                entity = "OPEN_SLOT_END_TYPE";
                allowed = List.of();
            }
            case "radiused" -> {
                type = Feature.SlotEnd.EndType.RADIUSED;
                entity = "RADIUSED_SLOT_END_TYPE";
                allowed = List.of();
            }
            case "loop" -> {
                type = Feature.SlotEnd.EndType.LOOP;
                entity = "LOOP_SLOT_END_TYPE";
                allowed = List.of();
            }
            case "flat" -> {
                type = Feature.SlotEnd.EndType.FLAT;
                entity = "FLAT_SLOT_END_TYPE";
                allowed = List.of("first radius", "second radius");
            }
            case "woodruff" -> {
                type = Feature.SlotEnd.EndType.WOODRUFF;
                entity = "WOODRUFF_SLOT_END_TYPE";
                allowed = List.of("radius");
            }
            default -> {
                return unreadEnd(
                        "#" + id + " SLOT_END '" + kind + "' (open, radiused, flat, woodruff and loop are known)");
            }
        }
        List<Long> items = shapeItems(id);
        List<String> foreign = foreignItems(items, allowed);
        if (!foreign.isEmpty()) {
            return unreadEnd("#" + id + " SLOT_END '" + kind + "' with " + String.join(", ", foreign)
                    + ", not read ("
                    + (allowed.isEmpty() ? "it has no parameters" : "its parameters are " + quoted(allowed))
                    + ")");
        }
        OptionalDouble first = OptionalDouble.empty();
        OptionalDouble second = OptionalDouble.empty();
        if (type == Feature.SlotEnd.EndType.FLAT) {
            first = lengthOf(namedMeasure(items, "first radius"));
            second = lengthOf(namedMeasure(items, "second radius"));
        } else if (type == Feature.SlotEnd.EndType.WOODRUFF) {
            first = lengthOf(namedMeasure(items, "radius"));
            if (first.isEmpty()) {
                return unreadEnd("#" + id + " SLOT_END 'woodruff' without its 'radius'");
            }
        }
        return new Feature.SlotEnd(type, entity, first, second);
    }

    /** The items that are not a measure of one of the allowed names, each as "'name'" or its type. */
    private List<String> foreignItems(List<Long> items, List<String> allowed) {
        List<String> out = new ArrayList<>();
        for (long i : items) {
            Item it = item(i);
            String name = it.name().trim().toLowerCase(Locale.ROOT);
            if (!(it.kind().equals("measure") && allowed.contains(name))) {
                out.add(it.kind().equals("measure") || !name.isEmpty() ? "'" + it.name() + "'" : typeOf(i));
            }
        }
        return out;
    }

    private static String quoted(List<String> names) {
        return names.stream()
                .map(n -> "'" + n + "'")
                .reduce((a, b) -> a + ", " + b)
                .orElse("");
    }

    private static boolean isOpen(Profile p) {
        return p instanceof Profile.General g && !g.closed() || p instanceof Profile.Linear || p instanceof Profile.U;
    }

    private static Optional<Long> first(Map<String, Long> components, String... names) {
        for (String n : names) {
            Long c = components.get(n);
            if (c != null) {
                return Optional.of(c);
            }
        }
        return Optional.empty();
    }

    private String bottomCondition(long id) {
        StepInstance i = inst(id);
        if (i == null) {
            return "?";
        }
        String kind = text(i.record().param(1)).trim().toUpperCase(Locale.ROOT).replace(' ', '_');
        return switch (i.record().type()) {
            case "HOLE_BOTTOM" ->
                switch (kind) {
                    case "THROUGH" -> "THROUGH_BOTTOM_CONDITION";
                    default -> kind + "_HOLE_BOTTOM";
                };
            case "POCKET_BOTTOM" -> kind + "_POCKET_BOTTOM_CONDITION";
            default -> i.record().type();
        };
    }

    /**
     * A PATH_FEATURE_COMPONENT as a course of travel in the feature frame, by its description (ISO
     * 10303-113 path_feature_component WR2): 'linear' is a LINEAR_PATH ('distance', and its
     * direction in a DIRECTION_SHAPE_REPRESENTATION), 'partial circular' a CIRCULAR_PATH ('radius',
     * 'sweep angle'), 'complete circular' a CIRCULAR_PATH of a full turn ('radius'), 'complex' a
     * GENERAL_PATH (its curve the 'profile shape' of its 'sweep path' PATH_SHAPE_REPRESENTATION).
     * Its placement is the PLACEMENT named 'orientation' among its parameters; the writer gives the
     * feature's own placement instance there for the feature frame. Another description keeps its
     * name, which the planner refuses.
     */
    private TravelPath travel(long id, Optional<Long> featurePlacement) {
        String kind = rec(id, "PATH_FEATURE_COMPONENT")
                .map(r -> text(r.param(1)).trim().toLowerCase(Locale.ROOT))
                .orElse("");
        List<Long> items = shapeItems(id);
        Optional<Vec3> dir = Optional.empty();
        Transform3 pl = Transform3.IDENTITY;
        Optional<Long> curve = Optional.empty();
        for (long i : items) {
            try {
                if (isA(i, "DIRECTION")) {
                    dir = Optional.of(geometry.directionOf(i));
                } else if (isA(i, "AXIS2_PLACEMENT_3D")
                        && !(featurePlacement.isPresent() && featurePlacement.get() == i)) {
                    pl = placement(i);
                } else if ((isA(i, "POLYLINE") || isA(i, "COMPOSITE_CURVE") || isA(i, "TRIMMED_CURVE"))
                        && (curve.isEmpty() || item(i).name().equalsIgnoreCase("profile shape"))) {
                    curve = Optional.of(i);
                }
            } catch (StepParseException e) {
                warnings.add(e.problem());
            }
        }
        OptionalDouble radius = lengthOf(namedMeasure(items, "radius"));
        switch (kind) {
            case "linear" -> {
                return new TravelPath(
                        "LINEAR_PATH",
                        pl,
                        lengthOf(namedMeasure(items, "distance")),
                        dir,
                        OptionalDouble.empty(),
                        OptionalDouble.empty());
            }
            case "partial circular", "complete circular" -> {
                // the model's sweep is the ARM's, in radians; the AIM's measure came in degrees
                OptionalDouble sweep = kind.equals("complete circular")
                        ? OptionalDouble.of(2 * Math.PI)
                        : lengthOf(namedMeasure(items, "sweep angle"));
                if (sweep.isPresent() && kind.equals("partial circular")) {
                    sweep = OptionalDouble.of(Math.toRadians(sweep.getAsDouble()));
                }
                return new TravelPath("CIRCULAR_PATH", pl, OptionalDouble.empty(), Optional.empty(), radius, sweep);
            }
            case "complex" -> {
                List<Profile.Segment> segments = List.of();
                if (curve.isPresent()) {
                    try {
                        Profile c = mm(geometry.curveProfile("GENERAL_PATH", id, Transform3.IDENTITY, curve));
                        if (c instanceof Profile.General g) {
                            segments = g.segments();
                        }
                    } catch (StepParseException e) {
                        warnings.add(e.problem());
                    }
                }
                return new TravelPath(
                        "GENERAL_PATH",
                        pl,
                        OptionalDouble.empty(),
                        Optional.empty(),
                        OptionalDouble.empty(),
                        OptionalDouble.empty(),
                        segments);
            }
            default -> {
                return new TravelPath(
                        "PATH_FEATURE_COMPONENT '" + kind + "'",
                        pl,
                        lengthOf(namedMeasure(items, "distance")),
                        dir,
                        radius,
                        OptionalDouble.empty());
            }
        }
    }

    /** A profile component (LINEAR_PROFILE, CIRCULAR_CLOSED_PROFILE, CLOSED_PATH_PROFILE, ...). */
    private Profile profile(long id, Optional<Long> featurePlacement) throws StepParseException {
        StepInstance i = inst(id);
        String entity = i == null ? "?" : i.record().type();
        List<Long> items = shapeItems(id);
        Transform3 pl = Transform3.IDENTITY;
        Optional<Long> curve = Optional.empty();
        for (long it : items) {
            if (isA(it, "AXIS2_PLACEMENT_3D") && !(featurePlacement.isPresent() && featurePlacement.get() == it)) {
                pl = placement(it);
            } else if (isA(it, "POLYLINE") || isA(it, "COMPOSITE_CURVE") || isA(it, "TRIMMED_CURVE")) {
                curve = Optional.of(it);
            }
        }
        // a dimension the profile does not give is not taken as 0, and a rectangle's corner radius
        // (which the ARM's rectangular_closed_profile has not: its pocket's orthogonal_radius rounds
        // the corners) is not dropped: a pocket milled to sharp corners would cut into them
        OptionalDouble length = lengthOf(namedMeasure(items, "profile length", "length"));
        OptionalDouble width = lengthOf(namedMeasure(items, "profile width", "width"));
        OptionalDouble diameter = lengthOf(namedMeasure(items, "diameter"));
        OptionalDouble corner = lengthOf(namedMeasure(items, "corner radius"));
        List<String> missing = new ArrayList<>();
        switch (entity) {
            case "LINEAR_PROFILE" -> {
                if (length.isEmpty()) {
                    missing.add("'length'");
                }
            }
            case "CIRCULAR_CLOSED_PROFILE" -> {
                if (diameter.isEmpty()) {
                    missing.add("'diameter'");
                }
            }
            case "RECTANGULAR_CLOSED_PROFILE" -> {
                if (width.isEmpty()) {
                    missing.add("'width'");
                }
                if (length.isEmpty()) {
                    missing.add("'length'");
                }
            }
            default -> {}
        }
        if (!missing.isEmpty()) {
            return new Profile.Other(entity + " without its " + String.join(" and ", missing), pl, id);
        }
        if (entity.equals("RECTANGULAR_CLOSED_PROFILE") && corner.isPresent() && corner.getAsDouble() > 0) {
            return new Profile.Other(
                    entity + " with a 'corner radius' of " + corner.getAsDouble()
                            + " mm, which the AIM binder does not read (milled square, its corners would be cut"
                            + " into)",
                    pl,
                    id);
        }
        return switch (entity) {
            case "LINEAR_PROFILE" -> new Profile.Linear(entity, pl, length.getAsDouble());
            case "CIRCULAR_CLOSED_PROFILE" -> new Profile.Circular(entity, pl, diameter.getAsDouble());
            case "RECTANGULAR_CLOSED_PROFILE" ->
                new Profile.Rectangular(entity, pl, width.getAsDouble(), length.getAsDouble());
            case "SQUARE_U_PROFILE", "ROUNDED_U_PROFILE", "VEE_PROFILE", "TEE_PROFILE", "PARTIAL_CIRCULAR_PROFILE" ->
                slotProfile(entity, id, pl, items);
            case "CLOSED_PATH_PROFILE", "OPEN_PATH_PROFILE" -> {
                Profile p = mm(geometry.curveProfile(
                        entity.equals("CLOSED_PATH_PROFILE") ? "GENERAL_CLOSED_PROFILE" : "GENERAL_PROFILE",
                        id,
                        pl,
                        curve));
                yield p;
            }
            default -> new Profile.Other(entity, pl, id);
        };
    }

    /**
     * The parameters of each slot profile the binding reads, by the names ISO 10303-113 gives them
     * (square_u_profile WR6-WR10, WR12; rounded_u_profile WR5, WR7; vee_profile WR7, WR8 and its
     * 'profile radius'; tee_profile WR6-WR9, WR12-WR14; partial_circular_profile WR5, WR6), each
     * an ARM attribute of ISO 14649-10's profile of the same name. 'depth' is checked against the
     * slot's depth by the feature.
     */
    private static final Map<String, List<String>> SLOT_PROFILE_PARAMETERS = Map.of(
            "SQUARE_U_PROFILE",
                    List.of("width", "first radius", "first angle", "second radius", "second angle", "depth"),
            "ROUNDED_U_PROFILE", List.of("width", "depth"),
            "VEE_PROFILE", List.of("profile radius", "profile angle", "tilt angle"),
            "TEE_PROFILE",
                    List.of(
                            "width",
                            "cross bar width",
                            "cross bar depth",
                            "radius",
                            "first angle",
                            "second angle",
                            "depth"),
            "PARTIAL_CIRCULAR_PROFILE", List.of("radius", "sweep angle"));

    /**
     * A slot's swept shape as the ARM binder makes it, angles in degrees as the measures' units
     * give them. A parameter the binding does not read (a vee's 'first length', a tee's 'first
     * offset', which ISO 14649-10's profiles do not have), or a required one missing, leaves the
     * profile unread ({@link Profile.Other}, named with why), which the planner refuses.
     */
    private Profile slotProfile(String entity, long id, Transform3 pl, List<Long> items) {
        List<String> allowed = SLOT_PROFILE_PARAMETERS.get(entity);
        // the profile's placement ('orientation') is read apart
        List<String> foreign = foreignItems(
                items.stream().filter(i -> !isA(i, "AXIS2_PLACEMENT_3D")).toList(), allowed);
        if (!foreign.isEmpty()) {
            return new Profile.Other(
                    entity + " with " + String.join(", ", foreign) + ", not read (its parameters are " + quoted(allowed)
                            + ")",
                    pl,
                    id);
        }
        Map<String, OptionalDouble> v = new HashMap<>();
        for (String n : allowed) {
            v.put(n, lengthOf(namedMeasure(items, n)));
        }
        List<String> required = switch (entity) {
            case "SQUARE_U_PROFILE", "ROUNDED_U_PROFILE" -> List.of("width");
            case "VEE_PROFILE" -> List.of("profile angle", "tilt angle");
            case "TEE_PROFILE" -> List.of("width", "cross bar width", "cross bar depth", "first angle", "second angle");
            default -> List.of("radius", "sweep angle");
        };
        List<String> missing = required.stream().filter(n -> v.get(n).isEmpty()).toList();
        if (!missing.isEmpty()) {
            return new Profile.Other(entity + " without its " + quoted(missing), pl, id);
        }
        return switch (entity) {
            case "SQUARE_U_PROFILE" ->
                new Profile.U(
                        entity,
                        pl,
                        v.get("width").getAsDouble(),
                        v.get("first radius"),
                        v.get("first angle"),
                        v.get("second radius"),
                        v.get("second angle"));
            case "ROUNDED_U_PROFILE" ->
                new Profile.U(
                        entity,
                        pl,
                        v.get("width").getAsDouble(),
                        OptionalDouble.empty(),
                        OptionalDouble.empty(),
                        OptionalDouble.empty(),
                        OptionalDouble.empty());
            case "VEE_PROFILE" ->
                new Profile.Vee(
                        entity,
                        pl,
                        v.get("profile radius"),
                        v.get("profile angle").getAsDouble(),
                        v.get("tilt angle").getAsDouble());
            case "TEE_PROFILE" ->
                new Profile.Tee(
                        entity,
                        pl,
                        v.get("width").getAsDouble(),
                        v.get("cross bar width").getAsDouble(),
                        v.get("cross bar depth").getAsDouble(),
                        v.get("radius"),
                        v.get("first angle").getAsDouble(),
                        v.get("second angle").getAsDouble());
            default ->
                new Profile.PartialCircular(
                        entity,
                        pl,
                        v.get("radius").getAsDouble(),
                        v.get("sweep angle").getAsDouble());
        };
    }

    // ---- operations ----

    private Operation operation(long id) throws StepParseException {
        StepInstance i = inst(id);
        String entity = i == null ? "?" : i.type();
        String kind = i == null || i.isComplex()
                ? ""
                : text(i.record().param(1)).trim().toLowerCase(Locale.ROOT);
        String opId = i == null || i.isComplex() ? "" : text(i.record().param(0));
        Operation.OperationType type = operationType(entity, kind);
        List<Property> props = actionProperties(id);
        Optional<Tool> tool = Optional.empty();
        for (long t : users.getOrDefault(id, List.of())) {
            Optional<StepRecord> r = rec(t, "MACHINING_TOOL");
            if (r.isPresent() && refs(r.get().param(2)).contains(id)) {
                tool = Optional.of(tool(t));
                break;
            }
        }
        Technology tech = Technology.NONE;
        Optional<Long> techId = firstUser(id, "MACHINING_TECHNOLOGY_RELATIONSHIP", 2)
                .flatMap(r -> ref(rec(r, "MACHINING_TECHNOLOGY_RELATIONSHIP")
                        .orElseThrow()
                        .param(3)));
        if (techId.isPresent()) {
            tech = technology(techId.get());
        }
        Optional<Strategy> strategy = Optional.empty();
        Optional<ApproachRetract> approach = Optional.empty();
        Optional<ApproachRetract> retract = Optional.empty();
        OptionalDouble diameter = tool.map(Tool::diameterMm).orElse(OptionalDouble.empty());
        for (long rel : usersOf(id, "MACHINING_STRATEGY_RELATIONSHIP", 2)) {
            StepRecord r = rec(rel, "MACHINING_STRATEGY_RELATIONSHIP").orElseThrow();
            Optional<Long> s = ref(r.param(3));
            if (s.isEmpty()) {
                continue;
            }
            switch (text(r.param(0)).toLowerCase(Locale.ROOT)) {
                case "approach" -> approach = Optional.of(approachRetract(s.get()));
                case "retract" -> retract = Optional.of(approachRetract(s.get()));
                default -> strategy = Optional.of(strategy(s.get(), diameter));
            }
        }
        Optional<Vec3> start = Optional.empty();
        Optional<Long> sp = itemOfType(property(props, "start point"), "CARTESIAN_POINT");
        if (sp.isPresent()) {
            start = Optional.of(mm(geometry.pointOf(sp.get())));
        }
        Optional<DrillingParameters> drilling = Optional.empty();
        if (type.isDrillingType()) {
            OptionalDouble feedOnRetract = measure(property(props, "feedrate on retract"));
            if (feedOnRetract.isPresent() && feedOnRetract.getAsDouble() > 1) {
                feedOnRetract = OptionalDouble.of(feedOnRetract.getAsDouble() / 100);
            }
            Optional<String> stop = description(property(props, "spindle stop at bottom"));
            drilling = Optional.of(new DrillingParameters(
                    measure(property(props, "dwell time bottom")),
                    feedOnRetract,
                    measure(property(props, "retract distance")),
                    measure(property(props, "first depth")),
                    measure(property(props, "depth of step")),
                    measure(property(props, "dwell time step")),
                    stop.map(x -> !x.toLowerCase(Locale.ROOT).contains("not")
                            && !x.toLowerCase(Locale.ROOT).contains("no "))));
        }
        List<ExplicitToolpath> toolpaths = toolpaths(id);
        if (!(tech.feedMmPerMin().orElse(0) > 0)) {
            // the feed is the cutting toolpaths' when the operation's own technology gives none
            // (Annex J.4: 0 at the operation, 250 mm/min on every cutting toolpath)
            Optional<Technology> cutting = toolpaths.stream()
                    .filter(t -> !t.rapid())
                    .map(ExplicitToolpath::technology)
                    .flatMap(Optional::stream)
                    .filter(t -> t.feedMmPerMin().orElse(0) > 0)
                    .findFirst();
            if (cutting.isPresent()) {
                spellings.add("an operation without a feed of its own takes its first cutting toolpath's technology");
                tech = cutting.get();
            }
        }
        return new Operation(
                id,
                type,
                kind.isEmpty() ? entity : entity + " '" + kind + "'",
                opId,
                measure(property(props, "retract plane")),
                start,
                tool,
                tech,
                strategy,
                approach,
                retract,
                measure(property(props, "axial cutting depth")),
                measure(property(props, "radial cutting depth")),
                measure(property(props, "allowance side")),
                measure(property(props, "allowance bottom")),
                measure(property(props, "cutting depth")),
                measure(property(props, "overcut length")),
                drilling,
                toolpaths);
    }

    // ---- explicit toolpaths (CC1) ----

    /** The operation's MACHINING_TOOLPATHs in sequence_position order. */
    private List<ExplicitToolpath> toolpaths(long op) throws StepParseException {
        List<long[]> rel = new ArrayList<>();
        List<Double> pos = new ArrayList<>();
        for (long r : usersOf(op, "MACHINING_TOOLPATH_SEQUENCE_RELATIONSHIP", 2)) {
            StepRecord x = rec(r, "MACHINING_TOOLPATH_SEQUENCE_RELATIONSHIP").orElseThrow();
            Optional<Long> tp = ref(x.param(3));
            if (tp.isPresent()) {
                rel.add(new long[] {tp.get()});
                pos.add(number(x.param(4)).orElse(Double.MAX_VALUE));
            }
        }
        List<Integer> idx = new ArrayList<>();
        for (int i = 0; i < rel.size(); i++) {
            idx.add(i);
        }
        idx.sort(Comparator.comparingDouble((Integer i) -> pos.get(i)).thenComparingInt(i -> i));
        List<ExplicitToolpath> out = new ArrayList<>();
        for (int i : idx) {
            long tp = rel.get(i)[0];
            StepInstance t = inst(tp);
            if (t == null || t.isComplex()) {
                continue;
            }
            List<Property> props = actionProperties(tp);
            boolean rapid = description(property(props, "speed profile"))
                    .map(x -> x.equalsIgnoreCase("rapid"))
                    .orElse(false);
            Optional<Technology> tech = firstUser(tp, "MACHINING_TECHNOLOGY_RELATIONSHIP", 2)
                    .flatMap(r -> ref(rec(r, "MACHINING_TECHNOLOGY_RELATIONSHIP")
                            .orElseThrow()
                            .param(3)))
                    .map(this::technology);
            Optional<Property> basic = property(props, "basic curve");
            List<Profile.Segment> curve = new ArrayList<>();
            if (basic.isPresent()) {
                for (long item : basic.get().items()) {
                    curve.addAll(curve(item, 0));
                }
            }
            if (property(props, "tool axis").isPresent()) {
                warnings.add(
                        "#" + tp + " MACHINING_TOOLPATH '" + text(t.record().param(0)) + "': its tool axis curve is"
                                + " not read; the tool stays along the feature's z axis");
            }
            out.add(new ExplicitToolpath(
                    tp, text(t.record().param(0)), text(t.record().param(1)), rapid, tech, curve));
        }
        return out;
    }

    /**
     * A curve as lines and arcs in the order it is traversed: POLYLINE, COMPOSITE_CURVE (its
     * segments' same_sense honoured), TRIMMED_CURVE of a LINE, POLYLINE or CIRCLE (ISO 10303-42:
     * from trim_1 to trim_2, along the circle's own sense when sense_agreement is true, against it
     * when false).
     */
    private List<Profile.Segment> curve(long id, int depth) throws StepParseException {
        if (depth > 8) {
            throw error(id, "curves nested more than 8 deep");
        }
        List<Profile.Segment> out = new ArrayList<>();
        if (isA(id, "POLYLINE")) {
            List<Vec3> pts = new ArrayList<>();
            for (long p : refs(rec(id, "POLYLINE").orElseThrow().param(1))) {
                pts.add(mm(geometry.pointOf(p)));
            }
            for (int i = 0; i + 1 < pts.size(); i++) {
                if (pts.get(i).distance(pts.get(i + 1)) > 0) {
                    out.add(new Profile.Line(pts.get(i), pts.get(i + 1)));
                }
            }
            return out;
        }
        if (isA(id, "COMPOSITE_CURVE")) {
            for (long seg : refs(rec(id, "COMPOSITE_CURVE").orElseThrow().param(1))) {
                StepRecord s = rec(seg, "COMPOSITE_CURVE_SEGMENT")
                        .orElseThrow(
                                () -> error(seg, "a composite curve's segment should be a COMPOSITE_CURVE_SEGMENT"));
                boolean same = !(s.param(1) instanceof StepValue.Enumeration e
                        && e.name().equals("F"));
                List<Profile.Segment> part = curve(
                        ref(s.param(2))
                                .orElseThrow(
                                        () -> error(seg, "COMPOSITE_CURVE_SEGMENT.parent_curve should be a reference")),
                        depth + 1);
                if (!same) {
                    part = reversed(part);
                }
                out.addAll(part);
            }
            return out;
        }
        if (isA(id, "TRIMMED_CURVE")) {
            StepRecord t = rec(id, "TRIMMED_CURVE").orElseThrow();
            Optional<Vec3> p1 = trimPoint(t.param(2));
            Optional<Vec3> p2 = trimPoint(t.param(3));
            if (p1.isEmpty() || p2.isEmpty()) {
                throw error(id, "TRIMMED_CURVE trimmed by parameters only: trim it by CARTESIAN_POINTs");
            }
            boolean sense =
                    !(t.param(4) instanceof StepValue.Enumeration e && e.name().equals("F"));
            long basis =
                    ref(t.param(1)).orElseThrow(() -> error(id, "TRIMMED_CURVE.basis_curve should be a reference"));
            if (isA(basis, "CIRCLE")) {
                StepRecord c = rec(basis, "CIRCLE").orElseThrow();
                Transform3 frame = placement(ref(c.param(1)).orElseThrow(() -> error(basis, "CIRCLE has no position")));
                double r = number(c.param(2)).orElseThrow(() -> error(basis, "CIRCLE has no radius")) * lengthScale;
                double z = frame.zAxis().z();
                if (Math.abs(Math.abs(z) - 1) > 1e-9) {
                    throw error(basis, "the arc's circle is not in a plane normal to z (axis " + frame.zAxis() + ")");
                }
                Vec3 centre = frame.translationPart();
                out.add(new Profile.Arc(p1.get(), p2.get(), centre, r, (z > 0) == sense));
                return out;
            }
            if (isA(basis, "LINE") || isA(basis, "POLYLINE")) {
                out.add(new Profile.Line(p1.get(), p2.get()));
                return out;
            }
            throw error(id, "TRIMMED_CURVE of a " + typeOf(basis) + ": lines and circles are read");
        }
        throw error(id, "a toolpath curve should be a POLYLINE, COMPOSITE_CURVE or TRIMMED_CURVE, found " + typeOf(id));
    }

    private Optional<Vec3> trimPoint(StepValue v) throws StepParseException {
        for (long p : refs(v)) {
            if (isA(p, "CARTESIAN_POINT")) {
                return Optional.of(mm(geometry.pointOf(p)));
            }
        }
        return Optional.empty();
    }

    private static List<Profile.Segment> reversed(List<Profile.Segment> in) {
        List<Profile.Segment> out = new ArrayList<>();
        for (int i = in.size() - 1; i >= 0; i--) {
            Profile.Segment s = in.get(i);
            out.add(
                    s instanceof Profile.Arc a
                            ? new Profile.Arc(a.end(), a.start(), a.center(), a.radiusMm(), !a.ccw())
                            : new Profile.Line(s.end(), s.start()));
        }
        return out;
    }

    /** The ARM operation an AIM operation entity and its description stand for. */
    static Operation.OperationType operationType(String entity, String kind) {
        boolean rough = kind.contains("rough");
        return switch (entity) {
            case "PLANE_MILLING_OPERATION" ->
                rough ? Operation.OperationType.PLANE_ROUGH_MILLING : Operation.OperationType.PLANE_FINISH_MILLING;
            case "SIDE_MILLING_OPERATION" ->
                rough ? Operation.OperationType.SIDE_ROUGH_MILLING : Operation.OperationType.SIDE_FINISH_MILLING;
            case "BOTTOM_AND_SIDE_MILLING_OPERATION" ->
                rough
                        ? Operation.OperationType.BOTTOM_AND_SIDE_ROUGH_MILLING
                        : Operation.OperationType.BOTTOM_AND_SIDE_FINISH_MILLING;
            case "DRILLING_OPERATION" ->
                switch (kind) {
                    case "center drilling" -> Operation.OperationType.CENTER_DRILLING;
                    case "counter sinking", "countersinking" -> Operation.OperationType.COUNTER_SINKING;
                    case "multistep drilling" -> Operation.OperationType.MULTISTEP_DRILLING;
                    default -> Operation.OperationType.DRILLING;
                };
            case "BORING_OPERATION" ->
                kind.contains("ream") ? Operation.OperationType.REAMING : Operation.OperationType.BORING;
            case "BACK_BORING_OPERATION" -> Operation.OperationType.BACK_BORING;
            case "TAPPING_OPERATION" -> Operation.OperationType.TAPPING;
            case "THREAD_DRILLING_OPERATION" -> Operation.OperationType.THREAD_DRILLING;
            case "FREEFORM_MILLING_OPERATION" -> Operation.OperationType.FREEFORM_OPERATION;
            default -> Operation.OperationType.OTHER;
        };
    }

    private Strategy strategy(long id, OptionalDouble toolDiameter) throws StepParseException {
        StepInstance i = inst(id);
        String entity = i == null ? "?" : i.record().type();
        String kind = i == null ? "" : text(i.record().param(1)).trim().toLowerCase(Locale.ROOT);
        List<Property> props = actionProperties(id);
        if (entity.equals("DRILLING_TYPE_STRATEGY")) {
            OptionalDouble[] ratios = new OptionalDouble[4];
            List<String> names = List.of(
                    "reduced cut at start",
                    "reduced feedrate at start",
                    "reduced cut at end",
                    "reduced feedrate at end");
            for (int k = 0; k < ratios.length; k++) {
                OptionalDouble v = measure(property(props, names.get(k)));
                if (v.isPresent() && v.getAsDouble() > 1) {
                    spellings.add("DRILLING_TYPE_STRATEGY ratios written as percentages (0-100)");
                    v = OptionalDouble.of(v.getAsDouble() / 100);
                }
                ratios[k] = v;
            }
            DrillingStrategy d = new DrillingStrategy(
                    ratios[0],
                    ratios[1],
                    measure(property(props, "depth of start")),
                    ratios[2],
                    ratios[3],
                    measure(property(props, "depth of end")));
            return Iso14649Binder.withoutMillingParameters(
                    id, Strategy.StrategyType.DRILLING_TYPE_STRATEGY, entity, Optional.of(d));
        }
        String arm = kind.toUpperCase(Locale.ROOT).replace(' ', '_');
        Strategy.StrategyType type = switch (arm) {
            case "UNIDIRECTIONAL",
                    "BIDIRECTIONAL",
                    "CONTOUR_PARALLEL",
                    "CONTOUR_SPIRAL",
                    "BIDIRECTIONAL_CONTOUR",
                    "CONTOUR_BIDIRECTIONAL",
                    "CENTER_MILLING",
                    "EXPLICIT" -> Strategy.StrategyType.valueOf(arm);
            default -> Strategy.StrategyType.OTHER;
        };
        OptionalDouble overlap = measure(property(props, "overlap ratio"));
        if (overlap.isEmpty()) {
            overlap = measure(property(props, "overlap"));
        }
        OptionalDouble fraction = OptionalDouble.empty();
        Optional<String> how = Optional.empty();
        if (overlap.isPresent()) {
            double v = overlap.getAsDouble();
            if (v >= 0 && v <= 1) {
                fraction = OptionalDouble.of(v);
                how = Optional.of("fraction");
                spellings.add("strategy overlap written as a fraction of the tool diameter (0-1)");
            } else if (v > 1 && v <= 100) {
                fraction = OptionalDouble.of(v / 100);
                how = Optional.of("percent");
                spellings.add("strategy overlap written as a percentage of the tool diameter (0-100)");
            } else {
                warnings.add("#" + id + " " + entity + ": overlap " + v + " is neither a fraction nor a percentage");
                how = Optional.of("unreadable");
            }
        }
        Optional<Boolean> multiple = description(property(props, "multiple passes"))
                .map(x -> !x.toLowerCase(Locale.ROOT).contains("not"));
        Optional<Vec3> feedDirection = Optional.empty();
        Optional<Long> fd = itemOfType(property(props, "feed direction"), "DIRECTION");
        if (fd.isPresent()) {
            feedDirection = Optional.of(geometry.directionOf(fd.get()));
        }
        Optional<String> stepover =
                description(property(props, "stepover direction")).map(x -> x.toUpperCase(Locale.ROOT));
        Optional<String> rotation = description(property(props, "rotation direction"))
                .map(x -> {
                    String l = x.toLowerCase(Locale.ROOT);
                    return l.contains("counter") || l.equals("ccw") ? "CCW" : "CW";
                });
        Optional<String> cutmode = description(property(props, "cutmode")).map(x -> x.toUpperCase(Locale.ROOT));
        return new Strategy(
                id,
                type,
                type == Strategy.StrategyType.OTHER ? entity + " '" + kind + "'" : arm,
                overlap,
                fraction,
                how,
                multiple,
                feedDirection,
                stepover,
                rotation,
                cutmode,
                Optional.empty());
    }

    private ApproachRetract approachRetract(long id) throws StepParseException {
        StepInstance i = inst(id);
        String kind = i == null
                ? ""
                : text(i.record().param(1)).trim().toUpperCase(Locale.ROOT).replace(' ', '_');
        ApproachRetract.Kind k;
        try {
            k = ApproachRetract.Kind.valueOf(kind);
        } catch (IllegalArgumentException ex) {
            k = ApproachRetract.Kind.OTHER;
        }
        List<Property> props = actionProperties(id);
        Optional<Vec3> orientation = Optional.empty();
        Optional<Long> d = itemOfType(property(props, "tool orientation"), "DIRECTION");
        if (d.isPresent()) {
            orientation = Optional.of(geometry.directionOf(d.get()));
        }
        OptionalDouble angle = measure(property(props, "plunge angle"));
        if (angle.isEmpty()) {
            angle = measure(property(props, "angle"));
        }
        return new ApproachRetract(
                id,
                k,
                k == ApproachRetract.Kind.OTHER ? typeOf(id) + " '" + kind + "'" : kind,
                orientation,
                angle,
                measure(property(props, "radius")),
                measure(property(props, "width")));
    }

    private Tool tool(long id) {
        Tool done = tools.get(id);
        if (done != null) {
            return done;
        }
        StepRecord t = rec(id, "MACHINING_TOOL").orElseThrow();
        String body = toolBody(text(t.param(1)));
        List<Long> bodyItems = new ArrayList<>();
        for (long rp : usersOf(id, "RESOURCE_PROPERTY", 2)) {
            StepRecord r = rec(rp, "RESOURCE_PROPERTY").orElseThrow();
            if (!text(r.param(0)).equalsIgnoreCase("tool body")) {
                continue;
            }
            for (long rpr : usersOf(rp, "RESOURCE_PROPERTY_REPRESENTATION", 2)) {
                Optional<Long> rep = ref(rec(rpr, "RESOURCE_PROPERTY_REPRESENTATION")
                        .orElseThrow()
                        .param(3));
                if (rep.isPresent()) {
                    bodyItems.addAll(items(rep.get()));
                    String name = text(inst(rep.get()).record().param(0));
                    if (!name.isEmpty()) {
                        body = toolBody(name);
                    }
                }
            }
        }
        OptionalDouble offset = OptionalDouble.empty();
        for (long arr : usersOf(id, "ACTION_RESOURCE_RELATIONSHIP", 2)) {
            Optional<Long> cc =
                    ref(rec(arr, "ACTION_RESOURCE_RELATIONSHIP").orElseThrow().param(3));
            if (cc.isPresent() && offset.isEmpty()) {
                for (long rp : usersOf(cc.get(), "RESOURCE_PROPERTY", 2)) {
                    for (long rpr : usersOf(rp, "RESOURCE_PROPERTY_REPRESENTATION", 2)) {
                        Optional<Long> rep = ref(rec(rpr, "RESOURCE_PROPERTY_REPRESENTATION")
                                .orElseThrow()
                                .param(3));
                        if (rep.isPresent()) {
                            for (long it : items(rep.get())) {
                                Item x = item(it);
                                if (x.kind().equals("measure") && offset.isEmpty()) {
                                    offset = x.value();
                                }
                            }
                        }
                    }
                }
            }
        }
        OptionalDouble teethValue = lengthOf(namedMeasure(bodyItems, "number of effective teeth", "number of teeth"));
        OptionalInt teeth = teethValue.isPresent() && teethValue.getAsDouble() >= 1 && teethValue.getAsDouble() < 1e6
                ? OptionalInt.of((int) Math.round(teethValue.getAsDouble()))
                : OptionalInt.empty();
        Optional<String> hand = Optional.empty();
        for (long it : bodyItems) {
            Item x = item(it);
            if (x.kind().equals("text") && x.name().equalsIgnoreCase("hand of cut")) {
                hand = Optional.of(x.text().toUpperCase(Locale.ROOT));
            }
        }
        Tool out = new Tool(
                id,
                text(t.param(0)),
                body,
                "MACHINING_TOOL_BODY_REPRESENTATION",
                lengthOf(namedMeasure(bodyItems, "effective cutting diameter", "diameter")),
                lengthOf(namedMeasure(bodyItems, "point angle", "tool top angle")),
                lengthOf(namedMeasure(bodyItems, "tool circumference angle")),
                lengthOf(namedMeasure(bodyItems, "maximum depth of cut", "cutting edge length")),
                lengthOf(namedMeasure(bodyItems, "edge radius")),
                lengthOf(namedMeasure(bodyItems, "edge center vertical")),
                lengthOf(namedMeasure(bodyItems, "edge center horizontal")),
                lengthOf(namedMeasure(bodyItems, "overall assembly length")),
                offset,
                teeth,
                hand,
                OptionalDouble.empty(),
                "deg");
        tools.put(id, out);
        return out;
    }

    /**
     * The ARM tool body a milling tool's AIM description stands for (ISO 10303-238
     * machining_tool WR6: 'ballnose endmill', 'tee slot mill' ...); the planner knows a ball end
     * mill and a T-slot mill by these names. Other kinds keep their description, upper case.
     */
    static String toolBody(String description) {
        String d = description.trim().toLowerCase(Locale.ROOT);
        return switch (d) {
            case "ballnose endmill" -> "BALL_ENDMILL";
            case "bullnose endmill" -> "BULLNOSE_ENDMILL";
            case "tee slot mill" -> "T_SLOT_MILL";
            case "dovetail mill" -> "DOVETAIL_MILL";
            default -> d.toUpperCase(Locale.ROOT).replace(' ', '_');
        };
    }

    private Technology technology(long id) {
        List<Property> props = actionProperties(id);
        Optional<Property> feed = property(props, "feedrate", "feed speed");
        Optional<Property> perTooth = property(props, "feedrate", "feed per tooth");
        Optional<Property> spindle = property(props, "spindle", "rotational speed");
        Optional<Property> cut = property(props, "spindle", "surface speed");
        Quantity f = quantity(feed);
        Quantity s = quantity(spindle);
        Quantity c = quantity(cut);
        Quantity z = quantity(perTooth);
        // the model's feed is mm/min and its spindle rpm: each value was converted by its own unit
        // (mm/s, in/min, 1/s ...) into mm/s and 1/s, so one factor of 60 remains
        OptionalDouble feedMmMin = f.converted().isPresent()
                ? OptionalDouble.of(f.converted().getAsDouble() * 60)
                : OptionalDouble.empty();
        OptionalDouble rpm = s.converted().isPresent()
                ? OptionalDouble.of(Math.abs(s.converted().getAsDouble()) * 60)
                : OptionalDouble.empty();
        boolean cw = s.converted().isPresent() && s.converted().getAsDouble() < 0;
        if (feedMmMin.isPresent() && feedMmMin.getAsDouble() > 0 && feedMmMin.getAsDouble() < SLOWEST_PLAUSIBLE_FEED) {
            // kept as written (a slow feed endangers nothing), but told: Annex J.6 writes the ARM's
            // 0.04 (m/s there) as 0.04 mm/s, a thousandth of the part's feed
            warnings.add("#" + id + " MACHINING_TECHNOLOGY: feed "
                    + num(f.written().getAsDouble()) + " " + f.unit()
                    + " is " + num(Math.round(feedMmMin.getAsDouble() * 1e4) / 1e4) + " mm/min, too slow to cut;"
                    + " kept as written (is the unit right? ISO 14649's ARM writes feeds in m/s)");
        }
        Optional<String> reference = description(property(props, "feedrate reference"))
                .map(x -> x.toLowerCase(Locale.ROOT).contains("contact") ? "CCP" : "TCP");
        return new Technology(
                id,
                f.written(),
                f.unit(),
                reference,
                c.written(),
                c.unit(),
                s.written(),
                s.unit(),
                z.converted(),
                feedMmMin,
                rpm,
                cw);
    }

    /** A measure as written, with its unit's name, and converted into model units (mm, s). */
    private record Quantity(OptionalDouble written, String unit, OptionalDouble converted) {}

    private Quantity quantity(Optional<Property> p) {
        if (p.isPresent()) {
            for (long i : p.get().items()) {
                StepInstance x = inst(i);
                if (x == null) {
                    continue;
                }
                StepRecord r = x.part("MEASURE_WITH_UNIT")
                        .orElse(x.part("MEASURE_REPRESENTATION_ITEM").orElse(null));
                if (r == null) {
                    continue;
                }
                int valueAt = r.type().equals("MEASURE_WITH_UNIT") ? 0 : 1;
                OptionalDouble v = number(r.param(valueAt));
                Unit u = ref(r.param(valueAt + 1)).map(id -> unit(id, 0)).orElse(new Unit(1, "unstated"));
                String label = ref(r.param(valueAt + 1))
                        .flatMap(id -> firstUser(id, "NAME_ATTRIBUTE", 1))
                        .flatMap(n -> rec(n, "NAME_ATTRIBUTE"))
                        .map(n -> text(n.param(0)))
                        .filter(n -> !n.isEmpty())
                        .orElse(u.label());
                return new Quantity(
                        v,
                        label.isEmpty() ? "unstated" : label,
                        v.isPresent() ? OptionalDouble.of(v.getAsDouble() * u.factor()) : v);
            }
        }
        return new Quantity(OptionalDouble.empty(), "unstated", OptionalDouble.empty());
    }
}
