/**
 * Sheet cutting: chaining, parts and holes, cut order, kerf, leads. Dependencies: {@code pocket}
 * (offsets), {@code dxf}, {@code model}, {@code geom}.
 */
package org.fresa.cutting;
