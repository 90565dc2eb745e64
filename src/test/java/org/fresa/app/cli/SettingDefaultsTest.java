package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.lang.reflect.RecordComponent;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.xml.parsers.DocumentBuilderFactory;
import org.fresa.job.JobSettings;
import org.fresa.setting.SettingChoice;
import org.fresa.setting.SettingRange;
import org.fresa.setting.SettingRanges;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;

/**
 * One set of defaults per module: every {@code default="..."} of the module's element in
 * {@code schemas/job.xsd} (what a job file without the attribute reads as) is the module's
 * defaults constant, and so is the default of the command-line option of the same setting.
 */
class SettingDefaultsTest {

    /**
     * A module: its element type in job.xsd, its defaults constant (record components named as
     * the attributes), the holder of its ranges and choices (option and attribute names) and its
     * command.
     */
    record Module(String xsdType, Record defaults, Class<?> holder, String command) {
        /** The setting of an attribute that is not a component of its own (the STEP-NC entry's parts). */
        Object nested(String attribute) throws Exception {
            if (defaults instanceof JobSettings.StepNcSettings s) {
                switch (attribute) {
                    case "entry":
                        return s.entry().kind();
                    case "entryAngleDeg":
                        return s.entry().angleDeg();
                    case "centreCutting":
                        return s.entry().centreCutting();
                    default:
                        break;
                }
            }
            if (defaults instanceof JobSettings.PocketSettings p) {
                switch (attribute) {
                    case "strategy":
                        return p.strategy().kind();
                    case "angleDeg":
                        return p.strategy().angleDeg();
                    case "stockToLeaveMm":
                        return p.strategy().stockToLeaveMm();
                    case "order":
                        return p.strategy().order();
                    default:
                        break;
                }
            }
            if (defaults instanceof JobSettings.RobotSettings r && attribute.equals("place")) {
                return r.placing();
            }
            if (defaults instanceof JobSettings.GradingSettings && attribute.equals("heelGroup")) {
                return JobSettings.HeelCoordination.DEFAULT_GROUP_SIZE;
            }
            return constant(defaults, attribute);
        }

        @Override
        public String toString() {
            return xsdType + (command == null ? "" : " and fresa " + command);
        }
    }

    static List<Module> modules() {
        return List.of(
                new Module("StepNcType", JobSettings.StepNcSettings.DEFAULTS, SettingRanges.StepNc.class, "toolpath"),
                new Module("StepNcType", JobSettings.StepNcSettings.DEFAULTS, SettingRanges.StepNc.class, "robot"),
                new Module("RobotType", JobSettings.RobotSettings.DEFAULTS, SettingRanges.Robot.class, "robot"),
                new Module("PocketType", JobSettings.PocketSettings.DEFAULTS, SettingRanges.Pocket.class, "pocket"),
                new Module("CuttingType", JobSettings.CuttingSettings.DEFAULTS, SettingRanges.Cutting.class, "cut"),
                new Module("GradingType", JobSettings.GradingSettings.DEFAULTS, SettingRanges.Grading.class, "grade"),
                // the sole has no command-line options (fresa sole JOB)
                new Module("SoleType", JobSettings.SoleSettings.DEFAULTS, SettingRanges.Sole.class, null));
    }

    /** The attribute defaults of a complex type of job.xsd. */
    static Map<String, String> xsdDefaults(String type) throws Exception {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setNamespaceAware(true);
        NodeList types = f.newDocumentBuilder()
                .parse(Path.of("schemas/job.xsd").toFile())
                .getElementsByTagNameNS("http://www.w3.org/2001/XMLSchema", "complexType");
        for (int i = 0; i < types.getLength(); i++) {
            Element t = (Element) types.item(i);
            if (t.getAttribute("name").equals(type)) {
                Map<String, String> out = new LinkedHashMap<>();
                NodeList attributes = t.getElementsByTagNameNS("http://www.w3.org/2001/XMLSchema", "attribute");
                for (int j = 0; j < attributes.getLength(); j++) {
                    Element a = (Element) attributes.item(j);
                    // only the type's own attributes, not those of nested elements
                    if (a.getParentNode() == t && a.hasAttribute("default")) {
                        out.put(a.getAttribute("name"), a.getAttribute("default"));
                    }
                }
                return out;
            }
        }
        throw new IllegalArgumentException(type);
    }

    /** The constant's value of a setting, by the attribute's name. */
    static Object constant(Record defaults, String attribute) throws Exception {
        for (RecordComponent c : defaults.getClass().getRecordComponents()) {
            if (c.getName().equals(attribute)) {
                return c.getAccessor().invoke(defaults);
            }
        }
        throw new IllegalArgumentException(
                "no setting " + attribute + " in " + defaults.getClass().getSimpleName());
    }

    /** Whether a value as written in job.xsd is the value: numbers by value, choices by their word. */
    static boolean same(String written, Object value, SettingChoice<?> choice) {
        if (value instanceof Double d) {
            return Double.parseDouble(written) == d;
        }
        if (value instanceof Enum<?> e && choice != null) {
            return written.equals(word(choice, e));
        }
        if (value instanceof Enum<?> e) {
            // an enumeration without a choice of its own is written by its word() or id()
            for (String method : List.of("word", "id")) {
                try {
                    return written.equals(e.getClass().getMethod(method).invoke(e));
                } catch (ReflectiveOperationException x) {
                    // try the next spelling
                }
            }
            return written.equals(String.valueOf(e));
        }
        if (value instanceof List<?> l) {
            return written.equals(
                    String.join(",", l.stream().map(String::valueOf).toList()));
        }
        return written.equals(String.valueOf(value));
    }

    @SuppressWarnings("unchecked")
    private static <E extends Enum<E>> String word(SettingChoice<E> choice, Enum<?> e) {
        return choice.word((E) e);
    }

    /** The choices of a holder, by attribute. */
    static Map<String, SettingChoice<?>> choices(Class<?> holder) throws Exception {
        Map<String, SettingChoice<?>> out = new LinkedHashMap<>();
        for (Field f : holder.getFields()) {
            if (Modifier.isStatic(f.getModifiers()) && f.get(null) instanceof SettingChoice<?> c) {
                out.put(c.attribute(), c);
            }
        }
        return out;
    }

    /** The command-line option of each attribute, from the holder's ranges and choices. */
    static Map<String, String> options(Class<?> holder) throws Exception {
        Map<String, String> out = new LinkedHashMap<>();
        for (Field f : holder.getFields()) {
            if (!Modifier.isStatic(f.getModifiers())) {
                continue;
            }
            Object v = f.get(null);
            if (v instanceof SettingRange r && !r.option().isEmpty()) {
                out.put(r.attribute(), r.option());
            } else if (v instanceof SettingChoice<?> c && !c.option().isEmpty()) {
                out.put(c.attribute(), c.option());
            }
        }
        return out;
    }

    @ParameterizedTest
    @MethodSource("modules")
    void theSchemaTheConstantAndTheCommandLineHaveTheSameDefaults(Module m) throws Exception {
        Map<String, String> xsd = xsdDefaults(m.xsdType());
        Map<String, SettingChoice<?>> choices = choices(m.holder());
        Map<String, String> options = options(m.holder());
        CommandLine command = m.command() == null
                ? null
                : FresaCommand.withAllCommands().getSubcommands().get(m.command());
        List<String> mismatches = new ArrayList<>();
        int compared = 0;
        for (Map.Entry<String, String> d : xsd.entrySet()) {
            String attribute = d.getKey();
            Object constant = m.nested(attribute);
            SettingChoice<?> choice = choices.get(attribute);
            if (!same(d.getValue(), constant, choice)) {
                mismatches.add(m.xsdType() + " " + attribute + ": job.xsd says " + d.getValue() + ", the constant "
                        + constant);
            }
            compared++;
            String option = options.get(attribute);
            if (option == null || command == null) {
                continue;
            }
            OptionSpec o = command.getCommandSpec().findOption(option);
            if (o == null || o.required() || o.initialValue() == null) {
                continue;
            }
            if (o.defaultValue() != null) {
                mismatches.add(m.command() + " " + option + ": declares its own default " + o.defaultValue()
                        + " instead of the constant's");
            } else if (o.initialValue() instanceof String text
                    ? !same(text, constant, choice)
                    : !o.initialValue().equals(constant)) {
                mismatches.add(m.command() + " " + option + ": defaults to " + o.initialValue() + ", the constant "
                        + constant);
            }
        }
        assertTrue(compared > 0, "no default compared in " + m.xsdType());
        assertEquals(List.of(), mismatches);
    }
}
