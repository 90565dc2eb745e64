package org.fresa.app.cli;

import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.model.CamInputException;
import org.fresa.setting.SettingRanges;
import org.fresa.toolpath.PlanningChoices;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * How {@code fresa toolpath} and {@code fresa robot} plan a STEP-NC file's workingsteps: whether a
 * doubtful cutting speed is trusted, how far through holes are passed, how pockets are entered and
 * whose path conventions are followed.
 */
final class StepNcPlanningOptions {

    @Option(
            names = "--trust-cutting-speed",
            description = "plan a workingstep whose spindle and cutting speed disagree tenfold from the cutting speed"
                    + " (else it is refused)")
    boolean trustCuttingSpeed = StepNcSettings.DEFAULTS.trustCuttingSpeed();

    @Option(
            names = "--breakthrough",
            paramLabel = "MM",
            description = "how far a through hole's drill (full diameter) or milling cutter passes the exit;"
                    + " default ${DEFAULT-VALUE} mm")
    double breakthroughMm = StepNcSettings.DEFAULTS.breakthroughMm();

    @Mixin
    StepNcEntryOptions entries = new StepNcEntryOptions();

    @Option(
            names = "--paths",
            paramLabel = "fresa|thesis",
            defaultValue = "fresa",
            description = "whose path conventions: fresa (exact arcs, gentle entries) or thesis (the 2016 STEP-NC robot"
                    + " thesis's points, docs/thesis-paths.md); default ${DEFAULT-VALUE}")
    String paths;

    /**
     * The planning choices asked for.
     *
     * @throws CamInputException (exit 2) naming the option whose value is out of range or unknown
     */
    PlanningChoices choices() throws CamInputException {
        return new PlanningChoices(
                trustCuttingSpeed,
                SettingRanges.StepNc.BREAKTHROUGH.check(breakthroughMm),
                entries.rule(),
                SettingRanges.StepNc.paths("--paths", paths));
    }
}
