function h = hertz_reference(A, B, Estar, F)
% Hertz's solution for h = A x^2 + B y^2 (A <= B; 1/m) pressed by the force F (N), combined modulus Estar (Pa):
% semi-axes a (along x) >= b, peak pressure p0 and approach delta (Johnson, Contact Mechanics, 4.39-4.41). The
% eccentricity e solves B/A = ((a/b)^2 E(e) - K(e)) / (K(e) - E(e)) with the complete elliptic integrals of Octave's
% ellipke (parameter m = e^2); A = B is the circle.
  if B / A - 1 < 1e-12
    a = (3 * F / (8 * Estar * A))^(1 / 3);
    h = struct('a', a, 'b', a, 'p0', 3 * F / (2 * pi * a^2), 'delta', 2 * A * a^2);
    return;
  end
  ratio = @(k) curvature_ratio(k) - B / A;
  k = fzero(ratio, [1e-4, 1 - 1e-9]);  % b / a
  m = 1 - k^2;
  [K, E] = ellipke(m);
  a = (3 * F * (K - E) / (2 * pi * Estar * m * A))^(1 / 3);
  b = k * a;
  p0 = 3 * F / (2 * pi * a * b);
  h = struct('a', a, 'b', b, 'p0', p0, 'delta', p0 * b / Estar * K);
end

function r = curvature_ratio(k)
  [K, E] = ellipke(1 - k^2);
  r = (E / k^2 - K) / (K - E);
end
