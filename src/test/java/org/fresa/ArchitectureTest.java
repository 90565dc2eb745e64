package org.fresa;

import static com.tngtech.archunit.base.DescribedPredicate.not;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAPackage;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAnyPackage;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static java.util.Map.entry;
import static org.junit.jupiter.api.Assertions.assertEquals;

import com.tngtech.archunit.core.domain.Dependency;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;
import com.tngtech.archunit.library.GeneralCodingRules;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

/**
 * The layering of docs/architecture.md, checked on every build: geometry at the bottom, domain
 * modules above it, the job services above those, the GUI and the command line on top.
 */
@AnalyzeClasses(packages = "org.fresa", importOptions = ImportOption.DoNotIncludeTests.class)
class ArchitectureTest {

    private static final String GEOM = "org.fresa.geom..";
    private static final String UI = "org.fresa.ui..";

    @ArchTest
    static final ArchRule layersPointOneWay = layeredArchitecture()
            .consideringOnlyDependenciesInLayers()
            .layer("Geometry")
            .definedBy(GEOM)
            .layer("Core")
            .definedBy("org.fresa.kin..", "org.fresa.model..")
            .layer("Domain")
            .definedBy(
                    "org.fresa.stepnc..",
                    "org.fresa.dxf..",
                    "org.fresa.pocket..",
                    "org.fresa.toolpath..",
                    "org.fresa.cutting..",
                    "org.fresa.grading..",
                    "org.fresa.sole..",
                    "org.fresa.post..")
            .layer("Chart")
            .definedBy("org.fresa.chart..")
            .layer("Io")
            .definedBy("org.fresa.io..")
            .layer("Robot")
            .definedBy("org.fresa.robot..")
            .layer("Setting")
            .definedBy("org.fresa.setting..")
            .layer("Cell")
            .definedBy("org.fresa.cell..")
            .layer("Service")
            .definedBy("org.fresa.job..")
            .layer("Bench")
            .definedBy("org.fresa.bench..")
            .layer("Ui")
            .definedBy(UI)
            .layer("App")
            .definedBy("org.fresa.app..")
            .whereLayer("App")
            .mayNotBeAccessedByAnyLayer()
            .whereLayer("Ui")
            .mayOnlyBeAccessedByLayers("App")
            .whereLayer("Bench")
            .mayOnlyBeAccessedByLayers("App")
            .whereLayer("Service")
            .mayOnlyBeAccessedByLayers("Bench", "Ui", "App")
            .whereLayer("Cell")
            .mayOnlyBeAccessedByLayers("Service", "Ui", "App")
            .whereLayer("Setting")
            .mayOnlyBeAccessedByLayers("Cell", "Service", "Ui", "App")
            .whereLayer("Chart")
            .mayOnlyBeAccessedByLayers("Service", "Ui", "App")
            .whereLayer("Robot")
            .mayOnlyBeAccessedByLayers("Setting", "Service", "Ui", "App")
            .whereLayer("Io")
            .mayOnlyBeAccessedByLayers("Robot", "Cell", "Service", "Ui", "App")
            .whereLayer("Domain")
            .mayOnlyBeAccessedByLayers("Domain", "Chart", "Robot", "Setting", "Cell", "Service", "Bench", "Ui", "App")
            .whereLayer("Core")
            .mayOnlyBeAccessedByLayers(
                    "Domain", "Chart", "Io", "Robot", "Setting", "Cell", "Service", "Bench", "Ui", "App")
            .because("dependencies point one way: geometry <- kinematics/model <- modules <- job <- ui/cli");

    @ArchTest
    static final ArchRule packagesAreFreeOfCycles = slices().matching("org.fresa.(*)..")
            .should()
            .beFreeOfCycles()
            .because("a cycle between packages makes the layers meaningless");

    @ArchTest
    static final ArchRule geometryDependsOnTheJdkOnly = classes()
            .that()
            .resideInAPackage(GEOM)
            .should()
            .onlyDependOnClassesThat()
            .resideInAnyPackage(GEOM, "java.lang..", "java.util..")
            .because("geometry is pure value types with no I/O and no libraries");

    @ArchTest
    static final ArchRule kinematicsDoesNotUseTheModel = noClasses()
            .that()
            .resideInAPackage("org.fresa.kin..")
            .should()
            .dependOnClassesThat()
            .resideInAnyPackage("org.fresa.model..", "org.fresa.stepnc..")
            .because("kinematics is a service on geometry alone");

    @ArchTest
    static final ArchRule readersNeverPlanPaths = noClasses()
            .that()
            .resideInAnyPackage("org.fresa.stepnc..", "org.fresa.dxf..")
            .should()
            .dependOnClassesThat()
            .resideInAnyPackage(
                    "org.fresa.pocket..",
                    "org.fresa.toolpath..",
                    "org.fresa.cutting..",
                    "org.fresa.post..",
                    "org.fresa.kin..")
            .because("readers turn files into models; planning is elsewhere");

    /**
     * The packages each package below {@code ui} may use, as its package-info states them
     * ("Dependencies: ..."); {@link PackageStatementsTest} keeps the two the same.
     */
    static final Map<String, List<String>> STATED_DEPENDENCIES = Map.ofEntries(
            entry("geom", List.of()),
            entry("kin", List.of("geom")),
            entry("model", List.of("geom")),
            entry("stepnc", List.of("model", "geom")),
            entry("dxf", List.of("model", "geom")),
            entry("pocket", List.of("geom", "model")),
            entry("pocket.compat", List.of("pocket", "model", "geom")),
            entry("toolpath", List.of("pocket", "stepnc", "model", "geom")),
            entry("cutting", List.of("pocket", "dxf", "model", "geom")),
            entry("grading", List.of("geom", "model")),
            entry("sole", List.of("pocket", "model", "geom")),
            entry("post", List.of("model", "geom")),
            entry("check", List.of("post", "geom")),
            entry("chart", List.of("model", "geom")),
            entry("io", List.of("model")),
            entry("robot", List.of("io", "post", "kin", "model", "geom")),
            entry(
                    "setting",
                    List.of(
                            "robot",
                            "dxf",
                            "pocket",
                            "toolpath",
                            "cutting",
                            "grading",
                            "sole",
                            "post",
                            "kin",
                            "model")),
            entry("cell", List.of("setting", "io", "stepnc", "toolpath", "kin", "model", "geom")),
            entry(
                    "job",
                    List.of(
                            "cell",
                            "setting",
                            "check",
                            "chart",
                            "io",
                            "robot",
                            "stepnc",
                            "dxf",
                            "pocket",
                            "toolpath",
                            "cutting",
                            "grading",
                            "sole",
                            "post",
                            "kin",
                            "model",
                            "geom")),
            entry("bench", List.of("job", "stepnc", "dxf", "pocket", "cutting", "post", "kin", "model")));

    /** No class of the package uses a Fresa package that its package-info does not state. */
    static ArchRule usesOnlyStatedPackages(String pkg) {
        List<String> allowed = STATED_DEPENDENCIES.get(pkg);
        String[] inside = Stream.concat(Stream.of(pkg), allowed.stream())
                .map(p -> "org.fresa." + p + "..")
                .toArray(String[]::new);
        return noClasses()
                .that()
                .resideInAPackage("org.fresa." + pkg + "..")
                .should()
                .dependOnClassesThat(resideInAPackage("org.fresa..").and(not(resideInAnyPackage(inside))))
                .because("the package-info of " + pkg + " states its dependencies: "
                        + (allowed.isEmpty() ? "none in Fresa" : String.join(", ", allowed)));
    }

    /**
     * Every stated arrow is a real one: each package uses every package its package-info names, so
     * that a dependency removed from the code is removed from the statement too.
     */
    @ArchTest
    static void everyStatedDependencyIsUsed(JavaClasses classes) {
        List<String> stale = new ArrayList<>();
        STATED_DEPENDENCIES.forEach((pkg, stated) -> {
            Set<String> used = new TreeSet<>();
            for (JavaClass c : classes) {
                if (!inside(c.getPackageName(), pkg)) {
                    continue;
                }
                for (Dependency d : c.getDirectDependenciesFromSelf()) {
                    String target = d.getTargetClass().getPackageName();
                    stated.stream()
                            .filter(s -> inside(target, s) && !inside(target, pkg))
                            .forEach(used::add);
                }
            }
            stated.stream().filter(s -> !used.contains(s)).forEach(s -> stale.add(pkg + " -> " + s));
        });
        assertEquals(List.of(), stale, "stated in a package-info but used by none of the package's classes");
    }

    /** Whether a package is {@code org.fresa.<pkg>} or below it. */
    private static boolean inside(String javaPackage, String pkg) {
        String p = "org.fresa." + pkg;
        return javaPackage.equals(p) || javaPackage.startsWith(p + ".");
    }

    @ArchTest
    static final ArchRule postDoesNotDependOnPocket = noClasses()
            .that()
            .resideInAPackage("org.fresa.post..")
            .should()
            .dependOnClassesThat()
            .resideInAPackage("org.fresa.pocket..")
            .because("a post writes a model toolpath in a control's dialect; the thesis's 7M post, which posts"
                    + " pocket passes, lives in pocket.compat");

    @ArchTest
    static final ArchRule geomUsesOnlyStatedPackages = usesOnlyStatedPackages("geom");

    @ArchTest
    static final ArchRule kinUsesOnlyStatedPackages = usesOnlyStatedPackages("kin");

    @ArchTest
    static final ArchRule modelUsesOnlyStatedPackages = usesOnlyStatedPackages("model");

    @ArchTest
    static final ArchRule stepncUsesOnlyStatedPackages = usesOnlyStatedPackages("stepnc");

    @ArchTest
    static final ArchRule dxfUsesOnlyStatedPackages = usesOnlyStatedPackages("dxf");

    @ArchTest
    static final ArchRule pocketUsesOnlyStatedPackages = usesOnlyStatedPackages("pocket");

    @ArchTest
    static final ArchRule pocketCompatUsesOnlyStatedPackages = usesOnlyStatedPackages("pocket.compat");

    @ArchTest
    static final ArchRule toolpathUsesOnlyStatedPackages = usesOnlyStatedPackages("toolpath");

    @ArchTest
    static final ArchRule cuttingUsesOnlyStatedPackages = usesOnlyStatedPackages("cutting");

    @ArchTest
    static final ArchRule gradingUsesOnlyStatedPackages = usesOnlyStatedPackages("grading");

    @ArchTest
    static final ArchRule soleUsesOnlyStatedPackages = usesOnlyStatedPackages("sole");

    @ArchTest
    static final ArchRule postUsesOnlyStatedPackages = usesOnlyStatedPackages("post");

    @ArchTest
    static final ArchRule checkUsesOnlyStatedPackages = usesOnlyStatedPackages("check");

    @ArchTest
    static final ArchRule chartUsesOnlyStatedPackages = usesOnlyStatedPackages("chart");

    @ArchTest
    static final ArchRule ioUsesOnlyStatedPackages = usesOnlyStatedPackages("io");

    @ArchTest
    static final ArchRule robotUsesOnlyStatedPackages = usesOnlyStatedPackages("robot");

    @ArchTest
    static final ArchRule settingUsesOnlyStatedPackages = usesOnlyStatedPackages("setting");

    @ArchTest
    static final ArchRule cellUsesOnlyStatedPackages = usesOnlyStatedPackages("cell");

    @ArchTest
    static final ArchRule jobUsesOnlyStatedPackages = usesOnlyStatedPackages("job");

    @ArchTest
    static final ArchRule benchUsesOnlyStatedPackages = usesOnlyStatedPackages("bench");

    @ArchTest
    static final ArchRule symjaOnlyInKinematics = noClasses()
            .that()
            .resideOutsideOfPackage("org.fresa.kin..")
            .should()
            .dependOnClassesThat()
            .resideInAPackage("org.matheclipse..")
            .because("kin's package-info names Symja as its dependency, for the symbolic forward kinematics only");

    @ArchTest
    static final ArchRule swingOnlyInUi = noClasses()
            .that()
            .resideOutsideOfPackage(UI)
            .should()
            .dependOnClassesThat()
            .resideInAPackage("javax.swing..")
            .because("Swing lives in the ui package only; everything else runs headless");

    @ArchTest
    static final ArchRule awtOnlyInChartAndUi = noClasses()
            .that()
            .resideOutsideOfPackages("org.fresa.chart..", UI)
            .and()
            .areNotAnnotatedWith(org.fresa.app.AllowedToUseAwt.class)
            .should()
            .dependOnClassesThat()
            .resideInAnyPackage("java.awt..", "org.jfree..")
            .because("drawing belongs to chart and ui; exceptions carry @AllowedToUseAwt with a reason");

    @ArchTest
    static final ArchRule viewModelsAreSwingFree = noClasses()
            .that()
            .haveSimpleNameEndingWith("ViewModel")
            .should()
            .dependOnClassesThat()
            .resideInAPackage("javax.swing..")
            .because("view models hold state and validation and are tested without a screen");

    @ArchTest
    static final ArchRule geometryIsImmutable = classes()
            .that()
            .resideInAPackage(GEOM)
            .should()
            .haveOnlyFinalFields()
            .because("geometry values are immutable");

    @ArchTest
    static final ArchRule standardStreamsOnlyInTheCommandLine = noClasses()
            .that()
            .resideOutsideOfPackage("org.fresa.app.cli..")
            .should(GeneralCodingRules.ACCESS_STANDARD_STREAMS)
            .because("only the command line talks to stdout and stderr");

    @ArchTest
    static final ArchRule noGenericExceptions = GeneralCodingRules.NO_CLASSES_SHOULD_THROW_GENERIC_EXCEPTIONS.because(
            "throw a CamInputException for bad input, an IllegalArgumentException for misuse");

    /**
     * The planners and engines the module services call for {@code fresa run} (through
     * {@code JobRunner}): a tab that called one itself would run its own pipeline beside the
     * service's, with other checks and choices. Their result types (nested records such as
     * {@code ToolpathPlanner.Plan}) may be shown; the computing classes themselves are the services'.
     */
    static final List<String> MODULE_PLANNERS = List.of(
            "org.fresa.stepnc.StepNcReader",
            "org.fresa.toolpath.ToolpathPlanner",
            "org.fresa.pocket.RegionPocket",
            "org.fresa.pocket.PassPlanner",
            "org.fresa.pocket.Recognition",
            "org.fresa.cutting.CutPlanner",
            "org.fresa.grading.Grader",
            "org.fresa.sole.TreadProgram",
            "org.fresa.sole.MouldBlock",
            "org.fresa.kin.TrajectorySolver");

    /** The rule over the given classes' package (the ui's, or a test fixture's). */
    static ArchRule tabsComputeThroughTheModuleServices(String pkg) {
        return noClasses()
                .that()
                .resideInAPackage(pkg)
                .should()
                .dependOnClassesThat(com.tngtech.archunit.base.DescribedPredicate.describe(
                        "are a module's planner or engine " + MODULE_PLANNERS,
                        (com.tngtech.archunit.core.domain.JavaClass c) -> MODULE_PLANNERS.contains(c.getName())))
                .because("a tab shows what fresa run writes only if both compute through the module's service"
                        + " (XService.compute(settings, progress)), never through a planner of their own");
    }

    @ArchTest
    static final ArchRule noTabRunsAPlannerOfItsOwn = tabsComputeThroughTheModuleServices(UI);
}
