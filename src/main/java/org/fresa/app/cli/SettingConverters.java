package org.fresa.app.cli;

import java.util.List;
import org.fresa.setting.SettingChoice;
import org.fresa.setting.SettingRanges;
import picocli.CommandLine;

/**
 * The enumerated options of every command, converted once where picocli parses them, with the
 * words of {@link SettingChoice} (the job file's words): a word that is no value is bad usage
 * (exit 2) with the allowed values named.
 */
final class SettingConverters {

    /** Every choice an option takes, one per enumeration. */
    static final List<SettingChoice<?>> CHOICES = List.of(
            SettingRanges.Pocket.POST,
            SettingRanges.Pocket.DIRECTION,
            SettingRanges.Pocket.ENTRY,
            SettingRanges.Pocket.STRATEGY,
            SettingRanges.Pocket.ORDER,
            SettingRanges.Cutting.PROCESS,
            SettingRanges.Cutting.LEAD,
            SettingRanges.Cutting.UNITS,
            SettingRanges.Cutting.POST,
            SettingRanges.Cutting.COMPENSATION,
            SettingRanges.Cutting.OUTER_DIRECTION,
            SettingRanges.StepNc.POST,
            SettingRanges.Grading.SYSTEM,
            SettingRanges.Grading.SHRINKAGE_MODE,
            SettingRanges.Robot.IK_METHOD);

    private SettingConverters() {}

    /** Registers the converters on a command line and the subcommands it has now. */
    static CommandLine register(CommandLine cl) {
        for (SettingChoice<?> c : CHOICES) {
            add(cl, c);
        }
        return cl;
    }

    private static <E extends Enum<E>> void add(CommandLine cl, SettingChoice<E> c) {
        cl.registerConverter(
                c.type(),
                text -> c.find(text).orElseThrow(() -> new CommandLine.TypeConversionException(c.problem(text))));
    }
}
