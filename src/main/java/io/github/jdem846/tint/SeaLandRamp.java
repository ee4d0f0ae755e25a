package io.github.jdem846.tint;

import io.github.jdem846.raster.ElevationStatistics;
import java.util.Objects;

/**
 * Two percent ramps split at sea level, each stretched over its own half of the DEM's range: the original
 * jDem846's default "standard" colouring. Elevations above 0 use {@code land} over
 * [max(min, 0), max(max, 0)]; elevations at or below 0 use {@code sea} over [min(min, 0), min(max, 0)]. A half
 * the DEM does not reach is the flat range [0, 0].
 *
 * @param name a short name for messages
 * @param land the ramp above sea level
 * @param sea  the ramp at and below sea level
 */
public record SeaLandRamp(String name, StopRamp land, StopRamp sea) implements ColorRamp {

    /**
     * Checks that the name and both ramps are given.
     *
     * @param name a short name for messages
     * @param land the ramp above sea level
     * @param sea the ramp at and below sea level
     */
    public SeaLandRamp {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(land, "land");
        Objects.requireNonNull(sea, "sea");
    }

    @Override
    public TintFunction bind(ElevationStatistics range) {
        return IntegerLookupTint.over(bindExact(range), range);
    }

    TintFunction bindExact(ElevationStatistics range) {
        ElevationStatistics landRange = range;
        ElevationStatistics seaRange = range;
        if (!range.isEmpty()) {
            DataRange r = DataRange.of(range);
            landRange = new ElevationStatistics(Math.max(r.min(), 0), Math.max(r.max(), 0), range.validCount(),
                    range.totalCount());
            seaRange = new ElevationStatistics(Math.min(r.min(), 0), Math.min(r.max(), 0), range.validCount(),
                    range.totalCount());
        }
        TintFunction above = land.bindExact(landRange);
        TintFunction below = sea.bindExact(seaRange);
        return elevation -> elevation != elevation ? Argb.TRANSPARENT
                : elevation > 0 ? above.argb(elevation) : below.argb(elevation);
    }
}
