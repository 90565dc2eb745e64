/**
 * DXF reading (ASCII and binary) into plane curves with layers. Dependencies: {@code model},
 * {@code geom}.
 */
package org.fresa.dxf;
