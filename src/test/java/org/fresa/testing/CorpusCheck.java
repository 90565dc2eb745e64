package org.fresa.testing;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.Tag;

/**
 * A test that reads files written by other programs (the corpus, {@link TestInputs}); counted in
 * the line at the end of {@code mvn verify} (see {@link CheckCounter}).
 */
@Target({ElementType.METHOD, ElementType.TYPE})
@Retention(RetentionPolicy.RUNTIME)
@Tag(CheckCounter.CORPUS)
public @interface CorpusCheck {}
