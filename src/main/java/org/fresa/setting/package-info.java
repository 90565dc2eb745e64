/**
 * The settings a planner gives, where they are read: the range of every numeric setting
 * ({@link org.fresa.setting.SettingRange}) and the words of every enumerated one
 * ({@link org.fresa.setting.SettingChoice}), one holder per module in
 * {@link org.fresa.setting.SettingRanges}, which the command line's options, the job file and the
 * tabs check against alike.
 *
 * <p>Dependencies: {@code robot} (the robot program formats), every domain package whose enumerated
 * settings it spells ({@code dxf}, {@code pocket}, {@code toolpath}, {@code cutting},
 * {@code grading}, {@code sole}, {@code post}), {@code kin} (the IK methods), {@code model}; never
 * {@code job}, {@code ui} or {@code app}.
 */
package org.fresa.setting;
