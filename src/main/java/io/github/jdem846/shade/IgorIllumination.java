package io.github.jdem846.shade;

import io.github.jdem846.light.LightDirection;

/**
 * gdaldem's {@code -igor} hillshade ({@code gdaldem hillshade -igor -compute_edges}, GDAL 3.6
 * {@code GDALHillshadeIgorAlg}, after Igor's terrain shading in Maperitive): no ambient "cos i" term, only slope and
 * aspect, so flat ground stays white and only slopes turned away from the light darken:
 * <pre>
 *   slopeStrength  = slope angle / 90°                                   (Horn's gradient, z-factor applied)
 *   aspectStrength = 1 − |downslope direction − direction the light travels| / 180°   (the angle between them)
 *   value          = 1 − slopeStrength · aspectStrength                  in (0, 1]
 * </pre>
 * The light's elevation is not used (gdaldem refuses {@code -alt} with {@code -igor}). gdaldem's byte is 255·value
 * ({@link HillshadeMethod#gray}). Same window and edge rules as {@link HornIllumination} ({@link GdalWindow}).
 * Deviation: gdaldem takes the aspect from the window's sums without the cell sizes; this uses the gradient in
 * metres, which is the same when cells are as tall as they are wide (projected grids, and geographic grids with
 * gdaldem's {@code -s}) and the true downslope direction otherwise.
 */
final class IgorIllumination extends HornWindowStage {

    IgorIllumination(HillshadeOptions options) {
        super(options);
    }

    @Override
    CellShader shader(LightDirection light) {
        final double zOver8 = options().zFactor() / 8.0;
        // The direction the light travels, as a mathematical angle (counter-clockwise from east).
        final double travel = normalize(1.5 * Math.PI - Math.toRadians(light.azimuthDegrees()));
        return (eastMinusWest, northMinusSouth, dx, dy) -> {
            final double slopeStrength = Math.toDegrees(slope(eastMinusWest, northMinusSouth, dx, dy, zOver8)) / 90;
            // downslope: the gradient (east, north) reversed, in metres (multiplied by dx·dy)
            final double downslope = normalize(Math.atan2(-northMinusSouth * dx, -eastMinusWest * dy));
            double diff = Math.abs(downslope - travel);
            if (diff > Math.PI) {
                diff = 2 * Math.PI - diff;
            }
            final double aspectStrength = 1 - diff / Math.PI;
            return (float) (1.0 - slopeStrength * aspectStrength);
        };
    }

    /** An angle in radians reduced into [0, 2π). */
    private static double normalize(double angle) {
        double a = angle % (2 * Math.PI);
        return a < 0 ? a + 2 * Math.PI : a;
    }
}
