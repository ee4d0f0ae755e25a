package io.github.jdem846.job;

/** What a {@link ReliefJob} makes. */
public enum Product {
    /** The main picture: tint × hillshade × cast shadows, 8-bit RGBA, no-data transparent. */
    RELIEF,
    /** The hillshade alone: 8-bit gray 1..255, 0 = no-data. */
    HILLSHADE,
    /** The colour ramp alone, 8-bit RGBA (like {@code gdaldem color-relief -alpha}). */
    TINT,
    /** The cast-shadow mask: 8-bit gray, 0 = lit, 255 = in shadow (soft shadows: the shadowed fraction). */
    SHADOWS,
    /** The sky-view factor ({@link io.github.jdem846.shadow.SkyView}): 8-bit gray 1..255 = 0..1, 0 = no-data. */
    SKY_VIEW
}
