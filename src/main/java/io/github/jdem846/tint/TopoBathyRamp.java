package io.github.jdem846.tint;

import io.github.jdem846.raster.ElevationStatistics;
import java.util.Objects;

/**
 * A land ramp that turns into a land ramp plus a sea ramp when a DEM holds both land and sea: the default tint.
 *
 * <p>When the range has min &lt; 0 &lt; max, elevations at or above 0 use {@code land} over [0, max] and elevations
 * below 0 use {@code sea} over [min, 0], so a cell at exactly 0 m gets the land ramp's first colour. Any other range
 * (land only, sea only, flat, no valid cell) binds {@code land} over [min, max], exactly as {@code land.bind} does.
 *
 * <p>This differs from {@link SeaLandRamp}, the original's "standard" colouring, which always splits and counts
 * 0 m as sea.
 *
 * @param name a short name for messages
 * @param land the ramp above sea level, and the whole ramp when the DEM does not hold both land and sea
 * @param sea  the ramp below sea level
 */
public record TopoBathyRamp(String name, StopRamp land, StopRamp sea) implements ColorRamp {

    /**
     * Checks that the name and both ramps are given.
     *
     * @param name a short name for messages
     * @param land the ramp above sea level, and the whole ramp when the DEM does not hold both land and sea
     * @param sea the ramp below sea level
     */
    public TopoBathyRamp {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(land, "land");
        Objects.requireNonNull(sea, "sea");
    }

    /**
     * {@return true when the range holds both land and sea (min &lt; 0 &lt; max), i.e. when the ramp splits at 0 m}
     *
     * @param range the DEM's valid elevations
     */
    public static boolean holdsLandAndSea(ElevationStatistics range) {
        return !range.isEmpty() && range.min() < 0 && range.max() > 0;
    }

    @Override
    public TintFunction bind(ElevationStatistics range) {
        if (!holdsLandAndSea(range)) {
            return land.bind(range);
        }
        return IntegerLookupTint.over(bindSplit(range), range);
    }

    /** The tint without a lookup table (the reference that the table reproduces). */
    TintFunction bindExact(ElevationStatistics range) {
        return holdsLandAndSea(range) ? bindSplit(range) : land.bindExact(range);
    }

    private TintFunction bindSplit(ElevationStatistics range) {
        DataRange r = DataRange.of(range);
        TintFunction above = land.bindExact(new ElevationStatistics(0, r.max(), range.validCount(),
                range.totalCount()));
        TintFunction below = sea.bindExact(new ElevationStatistics(r.min(), 0, range.validCount(),
                range.totalCount()));
        // NaN is not below 0, so no-data takes the land ramp's no-data colour; −0 counts as 0, i.e. land.
        return elevation -> elevation < 0 ? below.argb(elevation) : above.argb(elevation);
    }
}
