package io.github.jdem846.tint;

/** What a {@link ColorStop}'s level measures. */
public enum StopUnit {
    /** Percent of the DEM's range: 0 = its minimum, 100 = its maximum (the article's eq. 1, times 100). */
    PERCENT,
    /** An elevation in the DEM's vertical unit (metres for every DEM this project reads). */
    ABSOLUTE
}
