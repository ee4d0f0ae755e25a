package io.github.jdem846.tint;

import io.github.jdem846.raster.ElevationStatistics;
import java.util.Objects;

/**
 * A percent ramp whose range is spread by a {@link TintScale}. The scale is applied within each part of the range
 * that the ramp stretches on its own: [min, max], or [min, 0] and [0, max] for a ramp split at sea level
 * ({@link TopoBathyRamp} on land and sea, {@link SeaLandRamp}), so sea stays sea and land stays land.
 *
 * @param ramp  the ramp, with percent stops only
 * @param scale how its range is spread
 */
public record ScaledRamp(ColorRamp ramp, TintScale scale) implements ColorRamp {

    /**
     * Checks that ramp and scale are given, and that the ramp is neither scaled already nor has stops at fixed
     * elevations.
     *
     * @param ramp the ramp, with percent stops only
     * @param scale how its range is spread
     */
    public ScaledRamp {
        Objects.requireNonNull(ramp, "ramp");
        Objects.requireNonNull(scale, "scale");
        if (ramp instanceof ScaledRamp) {
            throw new IllegalArgumentException("ramp " + ramp.name() + " is already scaled");
        }
        if (hasAbsoluteStops(ramp)) {
            throw new IllegalArgumentException("ramp " + ramp.name() + " places colours at fixed elevations; a tint "
                    + "scale applies to ramps in percent of the DEM's range");
        }
    }

    @Override
    public String name() {
        return ramp.name() + " (" + scale.name().toLowerCase(java.util.Locale.ROOT) + ")";
    }

    @Override
    public TintFunction bind(ElevationStatistics range) {
        return IntegerLookupTint.over(bindExact(range), range);
    }

    /** The tint without a lookup table. */
    TintFunction bindExact(ElevationStatistics range) {
        TintFunction inner = exact(ramp, range);
        if (scale == TintScale.LINEAR) {
            return inner;
        }
        DataRange r = DataRange.of(range);
        double min = r.min();
        double max = r.max();
        boolean split = min < 0 && max > 0 && (ramp instanceof SeaLandRamp
                || ramp instanceof TopoBathyRamp && TopoBathyRamp.holdsLandAndSea(range));
        double mid = split ? 0 : max;
        return elevation -> {
            if (elevation != elevation) {
                return inner.argb(elevation);
            }
            double e = elevation;
            // Elevations beyond the range keep their value: the ramp gives them its end colours.
            if (e < min || e > max) {
                return inner.argb(elevation);
            }
            double lo = e <= mid ? min : mid;
            double hi = e <= mid ? mid : max;
            double span = hi - lo;
            float warped = span <= 0 ? elevation : (float) (lo + span * scale.apply((e - lo) / span, span));
            // Keep the side of sea level the elevation was on (a scale may round a position to 0).
            if (split && elevation < 0 && warped >= 0) {
                warped = Math.nextDown(0f);
            } else if (split && elevation > 0 && warped <= 0) {
                warped = Float.MIN_VALUE;
            }
            return inner.argb(warped);
        };
    }

    private static TintFunction exact(ColorRamp ramp, ElevationStatistics range) {
        if (ramp instanceof StopRamp s) {
            return s.bindExact(range);
        }
        if (ramp instanceof TopoBathyRamp t) {
            return t.bindExact(range);
        }
        if (ramp instanceof SeaLandRamp s) {
            return s.bindExact(range);
        }
        return ((ScaledRamp) ramp).bindExact(range);
    }

    private static boolean hasAbsoluteStops(ColorRamp ramp) {
        if (ramp instanceof StopRamp s) {
            return !s.isRelative();
        }
        if (ramp instanceof TopoBathyRamp t) {
            return !t.land().isRelative() || !t.sea().isRelative();
        }
        if (ramp instanceof SeaLandRamp s) {
            return !s.land().isRelative() || !s.sea().isRelative();
        }
        return hasAbsoluteStops(((ScaledRamp) ramp).ramp());
    }
}
