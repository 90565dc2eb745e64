package org.fresa.app.cli;

import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.model.CamInputException;
import org.fresa.pocket.EntryRule;
import org.fresa.setting.SettingRanges;
import picocli.CommandLine.Option;

/**
 * How {@code fresa toolpath} and {@code fresa robot} enter a STEP-NC file's pockets, by the names
 * {@code fresa pocket} uses: the kind of entry, the steepest descent and whether the file's milling
 * cutters cut at their centre (ISO 14649-111 does not say, so by default none is taken to).
 */
final class StepNcEntryOptions {

    @Option(
            names = "--entry",
            paramLabel = "auto|helix|ramp|plunge",
            description = "how pockets are entered: the file's own ramp or helix, else a helix where it has room,"
                    + " else a zig-zag ramp (auto), helix, ramp, or plunge (with --centre-cutting only);"
                    + " default ${DEFAULT-VALUE}")
    EntryRule.Kind entry = StepNcSettings.DEFAULTS.entry().kind();

    @Option(
            names = "--entry-angle",
            paramLabel = "DEG",
            description = "steepest descent of a pocket's helix or ramp entry and of a hole milled on a helix"
                    + " (deg, 0.5 to 90); default ${DEFAULT-VALUE}")
    double entryAngleDeg = StepNcSettings.DEFAULTS.entry().angleDeg();

    @Option(names = "--centre-cutting", description = "the file's milling cutters cut at their centre (may plunge)")
    boolean centreCutting = StepNcSettings.DEFAULTS.entry().centreCutting();

    /**
     * The entry rule asked for.
     *
     * @throws CamInputException (exit 2) for an angle out of range or a plunge of a
     *     cutter not said to cut at its centre
     */
    EntryRule rule() throws CamInputException {
        EntryRule.Kind kind = entry;
        double angle = SettingRanges.StepNc.ENTRY_ANGLE.check(entryAngleDeg);
        if (kind == EntryRule.Kind.PLUNGE && !centreCutting) {
            throw new CamInputException(
                    "--entry plunge",
                    "a plunge entry needs a centre-cutting tool: say so with"
                            + " --centre-cutting, or choose auto, helix or ramp");
        }
        return new EntryRule(kind, angle, centreCutting);
    }
}
