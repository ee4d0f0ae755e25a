/**
 * The sun's position from a date, a time and a place: the article's light source set "via formulas using date and
 * time" (casting-shadows article, §"Light source"), with the angles recomputed per tile when a DEM is large.
 *
 * <p>Positions come from NREL's Solar Position Algorithm (Reda &amp; Andreas 2004/2008, ±0.0003°) as implemented by
 * the {@code net.e175.klaus:solarpositioning} library. Entry points: {@link io.github.jdem846.sun.SolarCalculator}
 * for one place, {@link io.github.jdem846.sun.SunPerTile} for a grid, {@link io.github.jdem846.sun.TwilightFade} for
 * the original's darkening between zenith 90° and 108°, and {@link io.github.jdem846.sun.ZonedTimeParser} for the
 * time syntax the command line accepts. Earth only: see {@link io.github.jdem846.sun.Body}.
 */
package io.github.jdem846.sun;
