package io.github.jdem846.sun;

import java.time.LocalDate;
import java.util.OptionalDouble;
import net.e175.klaus.solarpositioning.DeltaT;

/**
 * Where the sun is seen from, apart from latitude and longitude: the observer's height and the air that refracts
 * the sunlight, and ΔT = TT − UT (the difference between the uniform time of the ephemeris and the Earth's
 * rotation).
 *
 * <p>Pressure and temperature only change the refraction, which lifts the sun by about 0.5° at the horizon and by
 * less than 0.02° above 45° elevation; the SPA applies it only while the sun is above about −0.83°. With an unknown
 * ΔT ({@link OptionalDouble#empty()}), {@link #deltaTSecondsFor(LocalDate)} uses the library's estimate for the date
 * (Espenak &amp; Meeus polynomials, valid for the years −1999 to 2999; 71.2 s for 2024, when the observed value was
 * about 69 s: a 2 s error moves the sun by 0.008°).
 *
 * @param heightMeters       height above sea level, in metres; −500 to 20 000
 * @param pressureMillibars  mean air pressure, in millibars (hPa); above 0 and at most 2000
 * @param temperatureCelsius mean air temperature, in °C; −100 to 100
 * @param deltaTSeconds      ΔT in seconds, or empty for the estimate for the date
 */
public record Observer(double heightMeters, double pressureMillibars, double temperatureCelsius,
                       OptionalDouble deltaTSeconds) {

    /** At sea level in the International Standard Atmosphere (1013.25 mbar, 15 °C), ΔT estimated. */
    public static final Observer SEA_LEVEL = atHeight(0);

    /**
     * Checks the ranges given in the record's description.
     *
     * @param heightMeters height above sea level, in metres; −500 to 20 000
     * @param pressureMillibars mean air pressure, in millibars (hPa); above 0 and at most 2000
     * @param temperatureCelsius mean air temperature, in °C; −100 to 100
     * @param deltaTSeconds ΔT in seconds, or empty for the estimate for the date
     */
    public Observer {
        if (!(heightMeters >= -500 && heightMeters <= 20_000)) {
            throw new IllegalArgumentException("observer height must be between -500 and 20000 m, got "
                    + heightMeters);
        }
        if (!(pressureMillibars > 0 && pressureMillibars <= 2000)) {
            throw new IllegalArgumentException("air pressure must be above 0 and at most 2000 mbar (sea level is "
                    + "about 1013), got " + pressureMillibars);
        }
        if (!(temperatureCelsius >= -100 && temperatureCelsius <= 100)) {
            throw new IllegalArgumentException("air temperature must be between -100 and 100 °C, got "
                    + temperatureCelsius);
        }
        if (deltaTSeconds == null) {
            deltaTSeconds = OptionalDouble.empty();
        }
        if (deltaTSeconds.isPresent() && !(Math.abs(deltaTSeconds.getAsDouble()) <= 200_000)) {
            throw new IllegalArgumentException("delta T must be a number of seconds within ±200000 (about 69 s in "
                    + "2024), got " + deltaTSeconds.getAsDouble());
        }
    }

    /**
     * An observer at {@code heightMeters} in the International Standard Atmosphere: pressure
     * 1013.25·(1 − 2.25577·10⁻⁵·h)^5.25588 mbar and temperature 15 − 0.0065·h °C; ΔT estimated.
     *
     * @param heightMeters height above sea level in metres, −500 to 20 000
     * @return the observer at that height, with the standard atmosphere's pressure and temperature there
     */
    public static Observer atHeight(double heightMeters) {
        double h = heightMeters;
        double pressure = 1013.25 * Math.pow(1 - 2.25577e-5 * h, 5.25588);
        double temperature = 15 - 0.0065 * h;
        return new Observer(h, pressure, temperature, OptionalDouble.empty());
    }

    /**
     * A copy with another air pressure in millibars.
     *
     * @param millibars the mean air pressure, above 0 and at most 2000
     * @return a new observer; this one is unchanged
     */
    public Observer withPressure(double millibars) {
        return new Observer(heightMeters, millibars, temperatureCelsius, deltaTSeconds);
    }

    /**
     * A copy with another air temperature in °C.
     *
     * @param celsius the mean air temperature, −100 to 100
     * @return a new observer; this one is unchanged
     */
    public Observer withTemperature(double celsius) {
        return new Observer(heightMeters, pressureMillibars, celsius, deltaTSeconds);
    }

    /**
     * A copy with a known ΔT in seconds.
     *
     * @param seconds ΔT = TT − UT, in seconds
     * @return a new observer; this one is unchanged
     */
    public Observer withDeltaT(double seconds) {
        return new Observer(heightMeters, pressureMillibars, temperatureCelsius, OptionalDouble.of(seconds));
    }

    /** {@return true when ΔT is estimated from the date rather than given} */
    public boolean isDeltaTEstimated() {
        return deltaTSeconds.isEmpty();
    }

    /**
     * ΔT in seconds for the given (UTC) date: the given value, or the estimate for the date.
     *
     * @param utcDate the date, in UTC, the estimate is made for
     * @return ΔT in seconds
     * @throws IllegalArgumentException when ΔT was not given and the date is outside the estimate's years
     */
    public double deltaTSecondsFor(LocalDate utcDate) {
        if (deltaTSeconds.isPresent()) {
            return deltaTSeconds.getAsDouble();
        }
        try {
            return DeltaT.estimate(utcDate);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("no delta T estimate for " + utcDate + " (the estimate covers the "
                    + "years -1999 to 2999); give delta T in seconds explicitly", e);
        }
    }
}
