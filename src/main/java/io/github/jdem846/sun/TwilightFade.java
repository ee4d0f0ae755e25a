package io.github.jdem846.sun;

/**
 * The original jDem846's twilight: the illumination of a cell is lowered as the sun sinks below the horizon, so a
 * date/time render darkens smoothly into night instead of switching off (jdem846-original.md §3, era B brightness,
 * and §4; defaults {@code lightingContext.lightZenith = 90}, {@code darkZenith = 108}, i.e. to the end of
 * astronomical twilight).
 *
 * <p>For an illumination d (the cosine of eq. 7, in [−1, 1]) and the sun's zenith angle z:
 * <pre>
 *   d − 2·(z − light)/(dark − light)   for light &lt; z ≤ dark
 *   d − 2                              for z &gt; dark
 *   d                                  for z ≤ light
 * </pre>
 * then clamped at −1 (fully dark). Pure and thread-safe; the compositor calls it once per cell.
 *
 * @param lightZenithDegrees the zenith angle where darkening starts (90: the sun on the horizon)
 * @param darkZenithDegrees  the zenith angle where it is complete (108: end of astronomical twilight)
 */
public record TwilightFade(double lightZenithDegrees, double darkZenithDegrees) {

    /** The original's 90° → 108°. */
    public static final TwilightFade ORIGINAL = new TwilightFade(90, 108);

    /**
     * Checks that 0 ≤ light zenith &lt; dark zenith ≤ 180.
     *
     * @param lightZenithDegrees the zenith angle where darkening starts (90: the sun on the horizon)
     * @param darkZenithDegrees the zenith angle where it is complete (108: end of astronomical twilight)
     */
    public TwilightFade {
        if (!(lightZenithDegrees >= 0 && darkZenithDegrees <= 180 && lightZenithDegrees < darkZenithDegrees)) {
            throw new IllegalArgumentException("twilight needs 0 <= light zenith < dark zenith <= 180 degrees, got "
                    + lightZenithDegrees + " and " + darkZenithDegrees);
        }
    }

    /**
     * How much is subtracted from the illumination at zenith angle {@code zenithDegrees}: 0 in daylight, rising
     * linearly to 2 at the dark zenith, 2 beyond. NaN for a NaN zenith.
     *
     * @param zenithDegrees the sun's zenith angle in degrees
     * @return the darkening, in [0, 2], or NaN
     */
    public double darkening(double zenithDegrees) {
        if (Double.isNaN(zenithDegrees)) {
            return Double.NaN;
        }
        if (zenithDegrees <= lightZenithDegrees) {
            return 0;
        }
        if (zenithDegrees > darkZenithDegrees) {
            return 2;
        }
        return 2 * (zenithDegrees - lightZenithDegrees) / (darkZenithDegrees - lightZenithDegrees);
    }

    /**
     * The illumination {@code d} faded for a sun at zenith angle {@code zenithDegrees}, clamped at −1. A NaN
     * {@code d} (no data) stays NaN.
     *
     * @param d the illumination, in [−1, 1], or NaN for no data
     * @param zenithDegrees the sun's zenith angle in degrees
     * @return the faded illumination, in [−1, 1], or NaN
     */
    public double apply(double d, double zenithDegrees) {
        return Math.max(-1, d - darkening(zenithDegrees));
    }
}
