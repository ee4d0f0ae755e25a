package io.github.jdem846.shade;

import io.github.jdem846.internal.Brightness;
import io.github.jdem846.internal.Clamp;
import io.github.jdem846.internal.Rounding;
import java.util.Objects;

/**
 * The hillshade methods: jDem846's own (the default) and gdaldem's four. Each makes an {@link IlluminationStage}
 * from {@link HillshadeOptions} and maps its illumination to the single-band gray byte of the {@code hillshade}
 * product, where 0 means no-data and 1 … 255 is light.
 */
public enum HillshadeMethod {

    /** Article section 3 (eq. 4–8), {@link JDem846Illumination}; gray by eq. 8 on mid-gray. */
    JDEM846 {
        @Override
        public IlluminationStage stage(HillshadeOptions options) {
            return new JDem846Illumination(options);
        }

        /**
         * Eq. 8 applied to mid-gray 0.5 after the jDem846 tone ({@link HillshadeOptions#tone}): 0.5·(1 + t) for
         * either sign of t, stretched onto 1 … 255, i.e. 1 + round(127·(1 + t)). t = −1 → 1, 0 → 128, 1 → 255.
         */
        @Override
        public int gray(float illumination, HillshadeOptions options) {
            if (Float.isNaN(illumination)) {
                return 0;
            }
            // Brightness.adjustBrightness(0.5, options.tone(illumination)) without branches on the sign, which a
            // hillshade makes unpredictable: the intensity factor is picked by the sign bit, and eq. 8 on 0.5 is
            // 0.5 + 0.5·t for either sign (0.5·(1 + t) for t < 0 rounds to the same double: halving is exact).
            // Equal bit for bit (HillshadeMethodTest).
            final double d = illumination;
            final long negative = Float.floatToRawIntBits(illumination) >> 31;
            final long light = Double.doubleToRawLongBits(options.relativeLightIntensity());
            final long dark = Double.doubleToRawLongBits(options.relativeDarkIntensity());
            double t = d * Double.longBitsToDouble(light ^ ((light ^ dark) & negative));
            if (options.spotExponent() != 1.0) {
                t = Brightness.spot(t, options.spotExponent());
            }
            final double channel = Clamp.between(0.5 + 0.5 * Clamp.between(t, -1.0, 1.0), 0.0, 1.0);
            return 1 + (int) Rounding.halfEven(254.0 * channel);
        }

        /** {@link #gray} written out in the loop, with the intensities read once. */
        @Override
        public void toGray(float[] illumination, int from, byte[] out, int to, int n, HillshadeOptions options) {
            if (options.spotExponent() != 1.0) {
                super.toGray(illumination, from, out, to, n, options);
                return;
            }
            final long light = Double.doubleToRawLongBits(options.relativeLightIntensity());
            final long dark = Double.doubleToRawLongBits(options.relativeDarkIntensity());
            for (int i = 0; i < n; i++) {
                final float v = illumination[from + i];
                final long negative = Float.floatToRawIntBits(v) >> 31;
                final double t = v * Double.longBitsToDouble(light ^ ((light ^ dark) & negative));
                final double channel = Clamp.between(0.5 + 0.5 * Clamp.between(t, -1.0, 1.0), 0.0, 1.0);
                out[to + i] = (byte) (v != v ? 0 : 1 + (int) Rounding.halfEven(254.0 * channel));
            }
        }
    },

    /** gdaldem's default (Horn) hillshade, {@link HornIllumination}; gray = gdaldem's bytes. */
    HORN {
        @Override
        public IlluminationStage stage(HillshadeOptions options) {
            return new HornIllumination(options);
        }

        /**
         * gdaldem: 1 + 254·cos i, or 1 where cos i ≤ 0, stored as float32 and rounded to the nearest byte (ties to
         * even, as GDAL's SSE float → byte conversion does).
         */
        @Override
        public int gray(float illumination, HillshadeOptions options) {
            if (Float.isNaN(illumination)) {
                return 0;
            }
            // toByte(cang254 <= 0 ? 1.0 : 1.0 + cang254) with cang254 = 254·illumination, without a branch on the
            // sign: a negative illumination (sign bit set) becomes +0, and from 1 up the byte is 255 (equal bit for
            // bit, HillshadeMethodTest).
            final int bits = Float.floatToRawIntBits(illumination);
            final float lit = Float.intBitsToFloat(bits & ~(bits >> 31));
            return lit >= 1f ? 255 : (int) Rounding.halfEven((float) (1.0 + 254.0 * lit));
        }

        /** {@link #gray} written out in the loop. */
        @Override
        public void toGray(float[] illumination, int from, byte[] out, int to, int n, HillshadeOptions options) {
            for (int i = 0; i < n; i++) {
                final float v = illumination[from + i];
                final int bits = Float.floatToRawIntBits(v);
                final float lit = Float.intBitsToFloat(bits & ~(bits >> 31));
                final int gray = lit >= 1f ? 255 : (int) Rounding.halfEven((float) (1.0 + 254.0 * lit));
                out[to + i] = (byte) (v != v ? 0 : gray);
            }
        }
    },

    /** gdaldem's {@code -multidirectional} hillshade, {@link MultidirectionalIllumination}; gray = gdaldem's bytes. */
    MULTIDIRECTIONAL {
        @Override
        public IlluminationStage stage(HillshadeOptions options) {
            return new MultidirectionalIllumination(options);
        }

        /**
         * gdaldem: 1 + 254·value rounded to the nearest byte. Deviation: clamped at 1, where gdaldem writes 0
         * (its no-data) for flat cells under a light more than 0.11° below the horizon.
         */
        @Override
        public int gray(float illumination, HillshadeOptions options) {
            if (Float.isNaN(illumination)) {
                return 0;
            }
            return Math.max(1, toByte(1.0 + 254.0 * illumination));
        }
    },

    /** gdaldem's {@code -combined} hillshade, {@link CombinedIllumination}; gray = gdaldem's bytes. */
    COMBINED {
        @Override
        public IlluminationStage stage(HillshadeOptions options) {
            return new CombinedIllumination(options);
        }

        /** gdaldem: 1 + 254·value, or 1 where value ≤ 0, rounded to the nearest byte like {@link #HORN}. */
        @Override
        public int gray(float illumination, HillshadeOptions options) {
            if (Float.isNaN(illumination)) {
                return 0;
            }
            return illumination <= 0 ? 1 : toByte(1.0 + 254.0 * illumination);
        }
    },

    /**
     * gdaldem's {@code -igor} hillshade, {@link IgorIllumination}: slope and aspect only, the light's elevation
     * unused; gray = gdaldem's bytes.
     */
    IGOR {
        @Override
        public IlluminationStage stage(HillshadeOptions options) {
            return new IgorIllumination(options);
        }

        /**
         * gdaldem: 255·value rounded to the nearest byte. Deviation: at least 1, where gdaldem would write 0 (its
         * no-data) for a slope within 0.2° of vertical facing straight away from the light.
         */
        @Override
        public int gray(float illumination, HillshadeOptions options) {
            if (Float.isNaN(illumination)) {
                return 0;
            }
            return Math.max(1, toByte(255.0 * illumination));
        }
    };

    /**
     * The illumination stage of this method with the given options.
     *
     * @param options z-factor, intensities and horizontal scale
     * @return the stage, which computes the illumination of a block of cells
     */
    public abstract IlluminationStage stage(HillshadeOptions options);

    /**
     * The gray byte (0 = no-data, 1 … 255) of one cell's illumination, as an int.
     *
     * @param illumination the illumination as this method's stage writes it; NaN for no-data
     * @param options the options the illumination was computed with
     * @return 0 for no-data, else 1 to 255
     */
    public abstract int gray(float illumination, HillshadeOptions options);

    /**
     * The gray bytes of a whole illumination array (as written by this method's stage), 0 = no-data. Read a byte as
     * unsigned: {@code out[i] & 0xFF}.
     *
     * @param illumination the illumination, row-major; NaN for no-data
     * @param options the options the illumination was computed with
     * @return one gray byte per value
     */
    public byte[] toGray(float[] illumination, HillshadeOptions options) {
        Objects.requireNonNull(illumination, "illumination");
        Objects.requireNonNull(options, "options");
        byte[] out = new byte[illumination.length];
        toGray(illumination, 0, out, 0, out.length, options);
        return out;
    }

    /**
     * The gray bytes of {@code n} illumination values: {@code out[to + i] = (byte) gray(illumination[from + i])}.
     * Horn and jdem846 write their conversion out in the loop: the first-tier JIT, which the launcher chooses for
     * small jobs, does not inline a call through this enum.
     *
     * @param illumination the illumination as this method's stage writes it; NaN for no-data
     * @param from the first value to convert
     * @param out receives the gray bytes
     * @param to where in {@code out} the first byte goes
     * @param n how many values to convert
     * @param options the options the illumination was computed with
     */
    public void toGray(float[] illumination, int from, byte[] out, int to, int n, HillshadeOptions options) {
        for (int i = 0; i < n; i++) {
            out[to + i] = (byte) gray(illumination[from + i], options);
        }
    }

    /** GDAL's float → byte store: the value as float32, clamped to 0 … 255, rounded to nearest (ties to even). */
    static int toByte(double value) {
        float f = (float) value;
        return (int) Rounding.halfEven(Clamp.between(f, 0f, 255f));
    }
}
