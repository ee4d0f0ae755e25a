package io.github.jdem846.shade;

import io.github.jdem846.internal.Clamp;
import io.github.jdem846.light.LightDirection;

/**
 * gdaldem's {@code -combined} hillshade ({@code gdaldem hillshade -combined -compute_edges}, GDAL 3.6
 * {@code GDALHillshadeCombinedAlg}): the Horn hillshade darkened by the slope, so steep ground is dark whichever
 * way it faces:
 * <pre>
 *   i     = acos(cos i)           the angle of incidence of {@link HornIllumination}, 0 … π
 *   value = 1 − i · slope / (π/2)²       slope = Horn's slope angle (z-factor applied), 0 … π/2;  value in (−1, 1]
 * </pre>
 * Flat ground gives 1 (white under any light). gdaldem's byte is 1 + 254·value, or 1 where value ≤ 0
 * ({@link HillshadeMethod#gray}). Same window and edge rules as {@link HornIllumination} ({@link GdalWindow}); the
 * cosine is computed multiplied through by Δx·Δy as there.
 */
final class CombinedIllumination extends HornWindowStage {

    private static final double INV_SQUARE_OF_HALF_PI = 4 / (Math.PI * Math.PI);

    CombinedIllumination(HillshadeOptions options) {
        super(options);
    }

    @Override
    CellShader shader(LightDirection light) {
        final double le = light.east();
        final double ln = light.north();
        final double lu = light.up();
        final double zOver8 = options().zFactor() / 8.0;
        return (eastMinusWest, northMinusSouth, dx, dy) -> {
            final double area = dx * dy;
            final double nx = -zOver8 * eastMinusWest * dy;
            final double ny = -zOver8 * northMinusSouth * dx;
            final double len = Math.sqrt(nx * nx + ny * ny + area * area);
            final double cos = len > 0 ? (nx * le + ny * ln + area * lu) / len : lu;
            final double incidence = Math.acos(Clamp.between(cos, -1.0, 1.0));
            final double slope = Math.atan2(Math.sqrt(nx * nx + ny * ny), area);
            return (float) (1 - incidence * slope * INV_SQUARE_OF_HALF_PI);
        };
    }
}
