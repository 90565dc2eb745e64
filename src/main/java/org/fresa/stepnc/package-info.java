/**
 * ISO 10303-21 (Part 21) reading and the ISO 14649 (STEP-NC) model bound from it. Readers never
 * plan paths. Dependencies: {@code model}, {@code geom}.
 *
 * <p>Two layers: {@link org.fresa.stepnc.Part21Reader} streams any Part 21 file into a
 * {@link org.fresa.stepnc.StepFile} (instances by name, values as written, references checked);
 * {@link org.fresa.stepnc.StepNcReader} binds it to a {@link org.fresa.stepnc.StepNcProgram}
 * through {@link org.fresa.stepnc.Iso14649Schema}, the entity subset described once in
 * {@code schemas/iso14649-subset.exp}. Lengths are mm; angles and technology values keep the
 * units the file uses, and the model says which.
 */
package org.fresa.stepnc;
